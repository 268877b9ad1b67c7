#pragma once
// Usage totals per (robot id, task id, backend), from the caller's gRPC metadata. Thread-safe.
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

struct UsageTotals {
  int64_t calls = 0;         // answered calls (including cache hits)
  int64_t cached_calls = 0;  // answered from the cache (no tokens spent)
  int64_t failed_calls = 0;  // calls that got no answer from any backend
  int64_t input_tokens = 0;
  int64_t output_tokens = 0;
};

struct UsageRow {
  std::string robot_id;
  std::string task_id;
  std::string backend;  // backend that answered; "" for failed calls
  UsageTotals totals;
};

class UsageLedger {
 public:
  void RecordAnswer(const CallerId& caller, const std::string& backend, const Usage& usage,
                    bool cached);
  void RecordFailure(const CallerId& caller);
  // Rows whose robot/task id equal the filters (an empty filter matches all), sorted by key.
  std::vector<UsageRow> Query(const std::string& robot_id, const std::string& task_id) const;

 private:
  using Key = std::tuple<std::string, std::string, std::string>;
  mutable absl::Mutex mu_;
  std::map<Key, UsageTotals> totals_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::modelproxy
