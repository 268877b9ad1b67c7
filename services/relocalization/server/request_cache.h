#pragma once

#include <cstddef>
#include <deque>
#include <map>
#include <optional>
#include <string>

namespace semnav::relocalization {

// Remembers the first successful answer per request_id (bounded, oldest forgotten first),
// so a retried transactional call returns that answer instead of applying twice.
// Not thread-safe: callers serialise transactional calls.
template <typename Response>
class RequestCache {
 public:
  explicit RequestCache(size_t capacity) : capacity_(capacity) {}

  std::optional<Response> Find(const std::string& request_id) const {
    const auto it = answers_.find(request_id);
    if (request_id.empty() || it == answers_.end()) return std::nullopt;
    return it->second;
  }

  void Remember(const std::string& request_id, const Response& response) {
    if (request_id.empty() || capacity_ == 0 || answers_.contains(request_id)) return;
    if (order_.size() == capacity_) {
      answers_.erase(order_.front());
      order_.pop_front();
    }
    order_.push_back(request_id);
    answers_.emplace(request_id, response);
  }

 private:
  const size_t capacity_;
  std::deque<std::string> order_;
  std::map<std::string, Response> answers_;
};

}  // namespace semnav::relocalization
