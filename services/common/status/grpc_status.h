#pragma once

#include <google/protobuf/message.h>
#include <grpcpp/support/status.h>

#include <optional>
#include <string>

#include "absl/status/status.h"
#include "absl/strings/cord.h"
#include "absl/strings/string_view.h"
#include "semnav/common/v1/errors.pb.h"

namespace semnav {

// The one place absl::Status becomes grpc::Status. Every absl payload whose type URL is
// "type.googleapis.com/<proto full name>" travels as a typed detail inside a RichStatus
// (wire-compatible with google.rpc.Status) in the grpc-status-details-bin trailer.
grpc::Status ToGrpcStatus(const absl::Status& status);

// The reverse, for clients: code and message; typed details stay readable via GetDetail.
absl::Status FromGrpcStatus(const grpc::Status& status);

// Attaches `detail` to a non-OK status as a typed payload (replacing one of the same type).
void AttachDetail(absl::Status& status, const google::protobuf::Message& detail);

// An error naming the offending request field, with an ErrorInfo detail {reason, field}.
absl::Status FieldError(absl::StatusCode code, absl::string_view field, absl::string_view message,
                        absl::string_view reason = "FIELD_INVALID");

// Raw serialized bytes of the first detail with the given full type name, if any.
std::optional<std::string> FindDetailBytes(const grpc::Status& status, absl::string_view full_name);

// The first detail of type M carried by a grpc::Status, if any.
template <typename M>
std::optional<M> GetDetail(const grpc::Status& status) {
  std::optional<std::string> bytes = FindDetailBytes(status, M::descriptor()->full_name());
  if (!bytes) return std::nullopt;
  M message;
  if (!message.ParseFromString(*bytes)) return std::nullopt;
  return message;
}

// The first detail of type M carried by an absl::Status payload, if any.
template <typename M>
std::optional<M> GetDetail(const absl::Status& status) {
  absl::optional<absl::Cord> payload =
      status.GetPayload("type.googleapis.com/" + std::string(M::descriptor()->full_name()));
  if (!payload) return std::nullopt;
  M message;
  if (!message.ParseFromString(std::string(*payload))) return std::nullopt;
  return message;
}

}  // namespace semnav
