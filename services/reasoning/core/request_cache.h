// Idempotency: the first answer to a transactional call, by method and request_id, kept for the
// last `capacity` requests (oldest forgotten first).
#pragma once

#include <deque>
#include <map>
#include <optional>
#include <string>

namespace semnav::reasoning {

class RequestCache {
 public:
  explicit RequestCache(std::size_t capacity) : capacity_(capacity == 0 ? 1 : capacity) {}

  std::optional<std::string> Find(const std::string& key) const {
    auto it = answers_.find(key);
    if (it == answers_.end()) return std::nullopt;
    return it->second;
  }
  void Put(const std::string& key, std::string answer) {
    if (!answers_.emplace(key, std::move(answer)).second) return;
    order_.push_back(key);
    if (order_.size() > capacity_) {
      answers_.erase(order_.front());
      order_.pop_front();
    }
  }

 private:
  std::size_t capacity_;
  std::map<std::string, std::string> answers_;
  std::deque<std::string> order_;
};

}  // namespace semnav::reasoning
