#include "services/modelproxy/core/response_cache.h"

namespace semnav::modelproxy {

std::optional<CachedAnswer> ResponseCache::Get(const std::string& key, absl::Time now) {
  absl::MutexLock lock(&mu_);
  auto it = index_.find(key);
  if (it == index_.end()) return std::nullopt;
  if (now - it->second->stored_at >= policy_.ttl) {
    lru_.erase(it->second);
    index_.erase(it);
    return std::nullopt;
  }
  lru_.splice(lru_.begin(), lru_, it->second);
  return it->second->answer;
}

void ResponseCache::Put(const std::string& key, CachedAnswer answer, absl::Time now) {
  if (policy_.capacity <= 0) return;
  absl::MutexLock lock(&mu_);
  if (auto it = index_.find(key); it != index_.end()) {
    lru_.erase(it->second);
    index_.erase(it);
  }
  lru_.push_front(Entry{key, std::move(answer), now});
  index_[key] = lru_.begin();
  if (static_cast<int>(lru_.size()) > policy_.capacity) {
    index_.erase(lru_.back().key);
    lru_.pop_back();
  }
}

int ResponseCache::size() const {
  absl::MutexLock lock(&mu_);
  return static_cast<int>(lru_.size());
}

}  // namespace semnav::modelproxy
