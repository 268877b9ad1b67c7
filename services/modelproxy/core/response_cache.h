#pragma once
// LRU cache with a time-to-live for completion answers, keyed by RequestKey(). Thread-safe.
#include <list>
#include <optional>
#include <string>
#include <unordered_map>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

struct CachePolicy {
  int capacity = 1024;  // entries; 0 disables the cache
  absl::Duration ttl = absl::Minutes(10);
};

// The part of an answer worth replaying.
struct CachedAnswer {
  BackendReply reply;
  std::string backend;  // backend name that produced it
};

class ResponseCache {
 public:
  explicit ResponseCache(CachePolicy policy) : policy_(policy) {}

  // The answer stored under `key` if present and younger than the TTL; refreshes its LRU rank.
  std::optional<CachedAnswer> Get(const std::string& key, absl::Time now);
  // Stores (or replaces) an answer, evicting the least recently used entry when full.
  void Put(const std::string& key, CachedAnswer answer, absl::Time now);
  int size() const;

 private:
  struct Entry {
    std::string key;
    CachedAnswer answer;
    absl::Time stored_at;
  };
  const CachePolicy policy_;
  mutable absl::Mutex mu_;
  std::list<Entry> lru_ ABSL_GUARDED_BY(mu_);  // front = most recently used
  std::unordered_map<std::string, std::list<Entry>::iterator> index_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::modelproxy
