#pragma once

#include <deque>
#include <optional>
#include <string>

#include <grpcpp/support/status.h>

#include "absl/container/flat_hash_map.h"
#include "absl/synchronization/mutex.h"

namespace semnav::mapping {

// First answers of transactional calls by request_id, so a retried call gets the same answer
// without repeating its effect. Keeps the newest `capacity` ids.
class IdempotencyCache {
 public:
  struct Answer {
    grpc::Status status;
    std::string response;  // serialized response message when status is OK
  };

  explicit IdempotencyCache(size_t capacity) : capacity_(capacity) {}

  // The stored answer for (method, request_id), if any.
  std::optional<Answer> Find(const std::string& method, const std::string& request_id) const;
  void Remember(const std::string& method, const std::string& request_id, Answer answer);

 private:
  size_t capacity_;
  mutable absl::Mutex mu_;
  absl::flat_hash_map<std::string, Answer> answers_ ABSL_GUARDED_BY(mu_);
  std::deque<std::string> order_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::mapping
