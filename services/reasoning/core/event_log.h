// Bounded operator event log with strictly increasing ids, replayable after a given id.
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "absl/time/time.h"

namespace semnav::reasoning {

struct LoggedEvent {
  uint64_t id = 0;
  absl::Time time;
  int kind = 0;  // the API's EventKind number
  std::string robot_id;
  std::string task_id;
  std::string message;
};

class EventLog {
 public:
  explicit EventLog(std::size_t retained) : retained_(retained == 0 ? 1 : retained) {}

  const LoggedEvent& Append(int kind, std::string robot_id, std::string task_id,
                            std::string message, absl::Time now);
  // Retained events with id > last_id of `robot_id` and `task_id` (either empty = any). `truncated`
  // is set when some events after last_id were already dropped.
  std::vector<LoggedEvent> After(uint64_t last_id, const std::string& robot_id,
                                 const std::string& task_id, bool* truncated) const;
  uint64_t last_id() const { return next_id_ - 1; }
  // Events kept from before a restart (ids ascending); the next id continues after them.
  void Restore(std::vector<LoggedEvent> events);

 private:
  std::size_t retained_;
  std::deque<LoggedEvent> events_;
  uint64_t next_id_ = 1;
};

}  // namespace semnav::reasoning
