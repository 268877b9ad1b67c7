// Operators' telemetry subscriptions as plain values (issue 18, item 5): who watches which
// robot, how often, and who is due a sample now. The subscriber is an opaque key (the server's
// stream); throttling lives here so the hub only sends.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "absl/time/time.h"

namespace semnav::reasoning {

template <typename Subscriber>
class TelemetrySubscriptions {
 public:
  // Replaces an earlier subscription of `subscriber`.
  void Add(Subscriber subscriber, std::string robot_id, absl::Duration interval) {
    subscriptions_[subscriber] = {std::move(robot_id), interval, absl::InfinitePast()};
  }
  void Remove(Subscriber subscriber) { subscriptions_.erase(subscriber); }

  // Subscribers of `robot_id` whose interval has passed since their last sample, marked as sent
  // at `now`.
  std::vector<Subscriber> TakeDue(const std::string& robot_id, absl::Time now) {
    std::vector<Subscriber> due;
    for (auto& [subscriber, entry] : subscriptions_) {
      if (entry.robot_id != robot_id || now - entry.last_sent < entry.interval) continue;
      entry.last_sent = now;
      due.push_back(subscriber);
    }
    return due;
  }
  // Every subscriber whose interval has passed, with its robot, marked as sent at `now`.
  std::vector<std::pair<Subscriber, std::string>> TakeDue(absl::Time now) {
    std::vector<std::pair<Subscriber, std::string>> due;
    for (auto& [subscriber, entry] : subscriptions_) {
      if (now - entry.last_sent < entry.interval) continue;
      entry.last_sent = now;
      due.emplace_back(subscriber, entry.robot_id);
    }
    return due;
  }
  // Every subscriber, forgotten (shutdown closes them).
  std::vector<Subscriber> TakeAll() {
    std::vector<Subscriber> all;
    for (const auto& [subscriber, entry] : subscriptions_) all.push_back(subscriber);
    subscriptions_.clear();
    return all;
  }

 private:
  struct Entry {
    std::string robot_id;
    absl::Duration interval;
    absl::Time last_sent;
  };
  std::map<Subscriber, Entry> subscriptions_;
};

}  // namespace semnav::reasoning
