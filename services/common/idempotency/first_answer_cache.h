// Idempotency for transactional calls: the first answer per key (method and request_id), kept
// for the newest `capacity` keys (oldest forgotten first), so a retried call gets that answer
// instead of applying twice. Not thread-safe: callers hold the lock that serialises the calls
// anyway (the check, the effect and the remembering must be one step).
#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>

namespace semnav {

template <typename Answer>
class FirstAnswerCache {
 public:
  // `capacity` 0 remembers nothing.
  explicit FirstAnswerCache(size_t capacity) : capacity_(capacity) {}

  std::optional<Answer> Find(const std::string& key) const {
    const auto it = answers_.find(key);
    if (it == answers_.end()) return std::nullopt;
    return it->second;
  }

  // Keeps the first answer for `key`; an empty key (no idempotency asked for) is never kept.
  void Remember(const std::string& key, Answer answer) {
    if (key.empty() || capacity_ == 0 || answers_.contains(key)) return;
    if (order_.size() == capacity_) {
      answers_.erase(order_.front());
      order_.pop_front();
    }
    order_.push_back(key);
    answers_.emplace(key, std::move(answer));
  }

  size_t size() const { return answers_.size(); }

 private:
  size_t capacity_;
  std::deque<std::string> order_;
  std::map<std::string, Answer> answers_;
};

}  // namespace semnav
