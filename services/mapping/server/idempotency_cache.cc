#include "services/mapping/server/idempotency_cache.h"

#include "absl/strings/str_cat.h"

namespace semnav::mapping {

std::optional<IdempotencyCache::Answer> IdempotencyCache::Find(const std::string& method,
                                                               const std::string& request_id) const {
  absl::MutexLock lock(&mu_);
  const auto it = answers_.find(absl::StrCat(method, "/", request_id));
  if (it == answers_.end()) return std::nullopt;
  return it->second;
}

void IdempotencyCache::Remember(const std::string& method, const std::string& request_id, Answer answer) {
  absl::MutexLock lock(&mu_);
  std::string key = absl::StrCat(method, "/", request_id);
  if (!answers_.insert_or_assign(key, std::move(answer)).second) return;
  order_.push_back(std::move(key));
  while (order_.size() > capacity_) {
    answers_.erase(order_.front());
    order_.pop_front();
  }
}

}  // namespace semnav::mapping
