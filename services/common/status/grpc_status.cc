#include "services/common/status/grpc_status.h"

#include <google/protobuf/any.pb.h>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/retry_after.h"

namespace semnav {
namespace {

constexpr absl::string_view kTypeUrlPrefix = "type.googleapis.com/";
constexpr size_t kMaxStatusMessageBytes = 1024;

}  // namespace

grpc::Status ToGrpcStatus(const absl::Status& status) {
  if (status.ok()) return grpc::Status::OK;
  // absl and gRPC share the canonical code numbering (0-16).
  const auto code = static_cast<grpc::StatusCode>(status.code());
  // Messages stay short whatever a request carried: clients have an 8 KB metadata limit.
  std::string message(status.message().substr(0, kMaxStatusMessageBytes));
  if (status.message().size() > kMaxStatusMessageBytes) message += "...";
  semnav::common::v1::RichStatus rich;
  rich.set_code(static_cast<int>(status.code()));
  rich.set_message(message);
  const std::string error_info_url =
      absl::StrCat(kTypeUrlPrefix, semnav::common::v1::ErrorInfo::descriptor()->full_name());
  std::optional<semnav::common::v1::ErrorInfo> attached;
  status.ForEachPayload([&](absl::string_view type_url, const absl::Cord& payload) {
    if (!absl::StartsWith(type_url, kTypeUrlPrefix)) return;
    if (type_url == error_info_url) {
      attached.emplace().ParseFromString(std::string(payload));
      return;
    }
    google::protobuf::Any* any = rich.add_details();
    any->set_type_url(std::string(type_url));
    any->set_value(std::string(payload));
  });
  // Every error carries an ErrorInfo: the field and reason core named, or the code's name; a
  // retry hint (a vendor's Retry-After) rides in its metadata.
  semnav::common::v1::ErrorInfo info;
  if (attached.has_value()) {
    info = *std::move(attached);
  } else {
    info.set_reason(ErrorReason(status).value_or(absl::StatusCodeToString(status.code())));
    info.set_field(ErrorField(status).value_or(""));
  }
  if (const std::optional<absl::Duration> after = RetryAfter(status); after.has_value()) {
    (*info.mutable_metadata())[kRetryAfterMetadataKey] = RetryAfterSecondsText(*after);
  }
  google::protobuf::Any* any = rich.add_details();
  any->set_type_url(error_info_url);
  any->set_value(info.SerializeAsString());
  return grpc::Status(code, message, rich.SerializeAsString());
}

absl::Status FromGrpcStatus(const grpc::Status& status) {
  if (status.ok()) return absl::OkStatus();
  absl::Status result(static_cast<absl::StatusCode>(status.error_code()), status.error_message());
  semnav::common::v1::RichStatus rich;
  if (!status.error_details().empty() && rich.ParseFromString(status.error_details())) {
    for (const google::protobuf::Any& any : rich.details()) {
      result.SetPayload(any.type_url(), absl::Cord(any.value()));
    }
    if (const std::optional<semnav::common::v1::ErrorInfo> info =
            GetDetail<semnav::common::v1::ErrorInfo>(result);
        info.has_value() && info->metadata().contains(kRetryAfterMetadataKey)) {
      if (const std::optional<absl::Duration> after =
              ParseRetryAfterSeconds(info->metadata().at(kRetryAfterMetadataKey));
          after.has_value()) {
        SetRetryAfter(result, *after);
      }
    }
  }
  return result;
}

void AttachDetail(absl::Status& status, const google::protobuf::Message& detail) {
  if (status.ok()) return;
  status.SetPayload(absl::StrCat(kTypeUrlPrefix, detail.GetDescriptor()->full_name()),
                    absl::Cord(detail.SerializeAsString()));
}

absl::Status FieldError(absl::StatusCode code, absl::string_view field, absl::string_view message,
                        absl::string_view reason) {
  // Core's FieldStatus plus the typed detail, for adapters and clients that read it before
  // ToGrpcStatus.
  absl::Status status = FieldStatus(code, field, message, reason);
  semnav::common::v1::ErrorInfo info;
  info.set_reason(std::string(reason));
  info.set_field(std::string(field));
  AttachDetail(status, info);
  return status;
}

std::optional<std::string> FindDetailBytes(const grpc::Status& status,
                                           absl::string_view full_name) {
  if (status.error_details().empty()) return std::nullopt;
  semnav::common::v1::RichStatus rich;
  if (!rich.ParseFromString(status.error_details())) return std::nullopt;
  const std::string wanted = absl::StrCat(kTypeUrlPrefix, std::string(full_name));
  for (const google::protobuf::Any& any : rich.details()) {
    if (any.type_url() == wanted) return any.value();
  }
  return std::nullopt;
}

}  // namespace semnav
