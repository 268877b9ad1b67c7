// Errors that name the request field they are about, for transport-free core code: the field
// and a stable reason travel as absl::Status payloads, and the one gRPC adapter
// (grpc_status.h, ToGrpcStatus) turns them into semnav.common.v1.ErrorInfo{reason, field}.
#pragma once

#include <optional>
#include <string>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"

namespace semnav {

// Payload type URLs of the field and the reason (not proto types: never sent as such).
inline constexpr absl::string_view kFieldPayloadUrl = "semnav.dev/error-field";
inline constexpr absl::string_view kReasonPayloadUrl = "semnav.dev/error-reason";

// `code` error "<field>: <why>" carrying the field and the reason (default FIELD_INVALID).
absl::Status FieldStatus(absl::StatusCode code, absl::string_view field, absl::string_view why,
                         absl::string_view reason = "FIELD_INVALID");
// The common case: INVALID_ARGUMENT about one field.
absl::Status InvalidField(absl::string_view field, absl::string_view why);

// The field / reason a status carries, if any.
std::optional<std::string> ErrorField(const absl::Status& status);
std::optional<std::string> ErrorReason(const absl::Status& status);

// The same error about `field` instead: for an adapter whose request names the field
// differently from core (two map ids in one request). The "<old field>: " message prefix core
// wrote is replaced; an error that named no field gets one. Code and reason are kept.
absl::Status WithField(const absl::Status& status, absl::string_view field);
// The same error with `reason` as its stable reason (the field, if any, is kept).
absl::Status WithReason(const absl::Status& status, absl::string_view reason);
// The same error with `reason` only where core gave none: adapters name the failing step
// (ALIGNMENT_FAILED, ...) while field errors keep the reason core chose.
absl::Status WithDefaultReason(const absl::Status& status, absl::string_view reason);

// A bad value as it may appear in a message: at most `max_chars` characters, then the size, so
// a 1 MB id is never echoed back (clients have an 8 KB metadata limit).
std::string Preview(absl::string_view value, size_t max_chars = 32);

}  // namespace semnav
