#include "services/reasoning/core/lease_table.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace semnav::reasoning {

LeaseTable::LeaseTable() : random_(std::random_device{}()) {}

std::optional<LeaseInfo> LeaseTable::Current(const std::string& robot_id, absl::Time now) const {
  auto it = by_robot_.find(robot_id);
  if (it == by_robot_.end() || it->second.expires_at <= now) return std::nullopt;
  return it->second;
}

std::vector<LeaseInfo> LeaseTable::Unexpired(absl::Time now) const {
  std::vector<LeaseInfo> out;
  for (const auto& [robot_id, lease] : by_robot_) {
    if (lease.expires_at > now) out.push_back(lease);
  }
  return out;
}

void LeaseTable::Restore(const std::vector<LeaseInfo>& leases, absl::Time now) {
  for (const LeaseInfo& lease : leases) {
    if (lease.expires_at > now && !lease.robot_id.empty()) by_robot_[lease.robot_id] = lease;
  }
}

absl::StatusOr<LeaseInfo> LeaseTable::Acquire(const std::string& robot_id,
                                              const std::string& holder, absl::Duration ttl,
                                              absl::Time now) {
  std::optional<LeaseInfo> current = Current(robot_id, now);
  if (current.has_value() && current->holder != holder) {
    return absl::FailedPreconditionError(absl::StrCat("lease of ", robot_id, " is held by ",
                                                      current->holder, " until ",
                                                      absl::FormatTime(current->expires_at)));
  }
  LeaseInfo lease = current.has_value()
                        ? *current
                        : LeaseInfo{absl::StrFormat("%016x", random_()), robot_id, holder, now};
  lease.expires_at = now + ttl;
  by_robot_[robot_id] = lease;
  return lease;
}

absl::StatusOr<LeaseInfo> LeaseTable::Renew(const std::string& lease_id, absl::Duration ttl,
                                            absl::Time now) {
  for (auto& [robot, lease] : by_robot_) {
    if (lease.lease_id != lease_id) continue;
    if (lease.expires_at <= now) break;
    lease.expires_at = now + ttl;
    return lease;
  }
  return absl::NotFoundError("unknown or expired lease");
}

void LeaseTable::Release(const std::string& lease_id) {
  for (auto it = by_robot_.begin(); it != by_robot_.end(); ++it) {
    if (it->second.lease_id == lease_id) {
      by_robot_.erase(it);
      return;
    }
  }
}

absl::Status LeaseTable::CheckControl(const std::string& robot_id, const std::string& lease_id,
                                      absl::Time now) const {
  std::optional<LeaseInfo> current = Current(robot_id, now);
  if (!current.has_value() || current->lease_id == lease_id) return absl::OkStatus();
  return absl::FailedPreconditionError(
      absl::StrCat("robot ", robot_id, " is leased by ", current->holder));
}

}  // namespace semnav::reasoning
