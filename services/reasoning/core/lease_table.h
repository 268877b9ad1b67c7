// Exclusive control leases per robot with a time to live: one holder at a time; controlling calls
// must present the lease id while an unexpired lease exists.
#pragma once

#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"

namespace semnav::reasoning {

struct LeaseInfo {
  std::string lease_id;
  std::string robot_id;
  std::string holder;
  absl::Time expires_at;
};

class LeaseTable {
 public:
  LeaseTable();
  // A new lease, or the holder's own unexpired one renewed; FAILED_PRECONDITION while another
  // holder's lease is unexpired.
  absl::StatusOr<LeaseInfo> Acquire(const std::string& robot_id, const std::string& holder,
                                    absl::Duration ttl, absl::Time now);
  // NOT_FOUND for unknown, released or expired leases.
  absl::StatusOr<LeaseInfo> Renew(const std::string& lease_id, absl::Duration ttl, absl::Time now);
  void Release(const std::string& lease_id);
  // OK when the robot has no unexpired lease or `lease_id` is it; FAILED_PRECONDITION otherwise.
  absl::Status CheckControl(const std::string& robot_id, const std::string& lease_id,
                            absl::Time now) const;
  std::optional<LeaseInfo> Current(const std::string& robot_id, absl::Time now) const;
  // Unexpired leases, for the gateway journal; Restore puts them back after a restart.
  std::vector<LeaseInfo> Unexpired(absl::Time now) const;
  void Restore(const std::vector<LeaseInfo>& leases, absl::Time now);

 private:
  std::map<std::string, LeaseInfo> by_robot_;
  std::mt19937_64 random_;
};

}  // namespace semnav::reasoning
