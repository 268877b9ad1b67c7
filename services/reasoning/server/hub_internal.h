// Helpers shared by the GatewayHub implementation files.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "absl/status/status.h"
#include "absl/time/time.h"
#include "google/protobuf/timestamp.pb.h"
#include "google/protobuf/util/time_util.h"
#include "semnav/reasoning/v1/operator.pb.h"
#include "services/common/idempotency/first_answer_cache.h"
#include "services/common/status/grpc_status.h"
#include "services/common/status/retry_after.h"
#include "services/reasoning/core/lease_table.h"

namespace semnav::reasoning::hub_internal {

namespace api = ::semnav::reasoning::v1;
using google::protobuf::util::TimeUtil;

inline absl::Status Required(const std::string& value, absl::string_view field) {
  if (!value.empty()) return absl::OkStatus();
  return FieldError(absl::StatusCode::kInvalidArgument, field, "is required");
}

// A failed model call's Retry-After (the vendor's, forwarded by the proxy), in seconds, for the
// task's call policy.
inline std::optional<double> RetryAfterSeconds(const absl::Status& status) {
  const std::optional<absl::Duration> after = RetryAfter(status);
  if (!after.has_value()) return std::nullopt;
  return absl::ToDoubleSeconds(*after);
}

inline google::protobuf::Timestamp ToTimestamp(absl::Time time) {
  return TimeUtil::NanosecondsToTimestamp(absl::ToUnixNanos(time));
}

inline api::Lease ToProto(const LeaseInfo& lease) {
  api::Lease out;
  out.set_lease_id(lease.lease_id);
  out.set_robot_id(lease.robot_id);
  out.set_holder(lease.holder);
  *out.mutable_expires_at() = ToTimestamp(lease.expires_at);
  return out;
}

// A repeated request_id returns the first answer, parsed back from the cache.
template <typename Response>
std::optional<Response> Cached(const FirstAnswerCache<std::string>& cache, const std::string& key) {
  std::optional<std::string> bytes = cache.Find(key);
  if (!bytes.has_value()) return std::nullopt;
  Response response;
  response.ParseFromString(*bytes);
  return response;
}

}  // namespace semnav::reasoning::hub_internal
