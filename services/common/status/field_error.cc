#include "services/common/status/field_error.h"

#include "absl/strings/cord.h"
#include "absl/strings/escaping.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"

namespace semnav {
namespace {

// The typed ErrorInfo an adapter's FieldError attaches (grpc_status.h). ToGrpcStatus prefers it
// to the payloads, so a renamed field or a new reason must not leave a stale one behind.
constexpr absl::string_view kTypedErrorInfoUrl = "type.googleapis.com/semnav.common.v1.ErrorInfo";

}  // namespace

absl::Status FieldStatus(absl::StatusCode code, absl::string_view field, absl::string_view why,
                         absl::string_view reason) {
  absl::Status status(code, absl::StrCat(field, ": ", why));
  status.SetPayload(kFieldPayloadUrl, absl::Cord(field));
  status.SetPayload(kReasonPayloadUrl, absl::Cord(reason));
  return status;
}

absl::Status InvalidField(absl::string_view field, absl::string_view why) {
  return FieldStatus(absl::StatusCode::kInvalidArgument, field, why);
}

std::optional<std::string> ErrorField(const absl::Status& status) {
  absl::optional<absl::Cord> payload = status.GetPayload(kFieldPayloadUrl);
  if (!payload) return std::nullopt;
  return std::string(*payload);
}

std::optional<std::string> ErrorReason(const absl::Status& status) {
  absl::optional<absl::Cord> payload = status.GetPayload(kReasonPayloadUrl);
  if (!payload) return std::nullopt;
  return std::string(*payload);
}

absl::Status WithField(const absl::Status& status, absl::string_view field) {
  if (status.ok()) return status;
  absl::string_view why = status.message();
  if (const std::optional<std::string> old_field = ErrorField(status)) {
    absl::ConsumePrefix(&why, absl::StrCat(*old_field, ": "));
  }
  absl::Status out(status.code(), absl::StrCat(field, ": ", why));
  status.ForEachPayload([&](absl::string_view url, const absl::Cord& payload) {
    if (url != kTypedErrorInfoUrl) out.SetPayload(url, payload);
  });
  out.SetPayload(kFieldPayloadUrl, absl::Cord(field));
  return out;
}

absl::Status WithReason(const absl::Status& status, absl::string_view reason) {
  if (status.ok()) return status;
  absl::Status out = status;
  out.ErasePayload(kTypedErrorInfoUrl);
  out.SetPayload(kReasonPayloadUrl, absl::Cord(reason));
  return out;
}

absl::Status WithDefaultReason(const absl::Status& status, absl::string_view reason) {
  if (status.ok() || ErrorReason(status).has_value()) return status;
  return WithReason(status, reason);
}

std::string Preview(absl::string_view value, size_t max_chars) {
  // Escaped: a bad value may hold any bytes, a message is for people and logs.
  if (value.size() <= max_chars) return absl::CEscape(value);
  return absl::StrCat(absl::CEscape(value.substr(0, max_chars)), "... (", value.size(), " bytes)");
}

}  // namespace semnav
