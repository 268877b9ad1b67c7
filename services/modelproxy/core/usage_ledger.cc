#include "services/modelproxy/core/usage_ledger.h"

namespace semnav::modelproxy {

void UsageLedger::RecordAnswer(const CallerId& caller, const std::string& backend,
                               const Usage& usage, bool cached) {
  absl::MutexLock lock(&mu_);
  UsageTotals& t = totals_[Key{caller.robot_id, caller.task_id, backend}];
  ++t.calls;
  if (cached) {
    ++t.cached_calls;
    return;
  }
  t.input_tokens += usage.input_tokens;
  t.output_tokens += usage.output_tokens;
}

void UsageLedger::RecordFailure(const CallerId& caller) {
  absl::MutexLock lock(&mu_);
  ++totals_[Key{caller.robot_id, caller.task_id, ""}].failed_calls;
}

std::vector<UsageRow> UsageLedger::Query(const std::string& robot_id,
                                         const std::string& task_id) const {
  absl::MutexLock lock(&mu_);
  std::vector<UsageRow> rows;
  for (const auto& [key, totals] : totals_) {
    const auto& [robot, task, backend] = key;
    if (!robot_id.empty() && robot != robot_id) continue;
    if (!task_id.empty() && task != task_id) continue;
    rows.push_back(UsageRow{robot, task, backend, totals});
  }
  return rows;
}

}  // namespace semnav::modelproxy
