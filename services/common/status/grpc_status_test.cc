#include "services/common/status/grpc_status.h"

#include <gtest/gtest.h>

#include "services/common/status/field_error.h"
#include "services/common/status/retry_after.h"

namespace semnav {
namespace {

using semnav::common::v1::ErrorInfo;

TEST(GrpcStatusTest, OkMapsToOk) { EXPECT_TRUE(ToGrpcStatus(absl::OkStatus()).ok()); }

TEST(GrpcStatusTest, CodesAndMessagesSurvive) {
  const grpc::Status s = ToGrpcStatus(absl::NotFoundError("map 'lab' not found"));
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(s.error_message(), "map 'lab' not found");
  // An error about no field still carries an ErrorInfo: its reason is the code's name.
  std::optional<ErrorInfo> info = GetDetail<ErrorInfo>(s);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->reason(), "NOT_FOUND");
  EXPECT_EQ(info->field(), "");
  EXPECT_EQ(ToGrpcStatus(absl::DeadlineExceededError("x")).error_code(),
            grpc::StatusCode::DEADLINE_EXCEEDED);
  EXPECT_EQ(ToGrpcStatus(absl::DataLossError("x")).error_code(), grpc::StatusCode::DATA_LOSS);
  EXPECT_EQ(ToGrpcStatus(absl::UnauthenticatedError("x")).error_code(),
            grpc::StatusCode::UNAUTHENTICATED);
}

TEST(GrpcStatusTest, FieldErrorCarriesTypedDetailAcrossTheAdapter) {
  const absl::Status error =
      FieldError(absl::StatusCode::kInvalidArgument, "frame.depth.width", "640 != intrinsics 320");
  EXPECT_EQ(error.message(), "frame.depth.width: 640 != intrinsics 320");
  const grpc::Status wire = ToGrpcStatus(error);
  EXPECT_EQ(wire.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  std::optional<ErrorInfo> info = GetDetail<ErrorInfo>(wire);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->field(), "frame.depth.width");
  EXPECT_EQ(info->reason(), "FIELD_INVALID");

  const absl::Status back = FromGrpcStatus(wire);
  EXPECT_EQ(back.code(), absl::StatusCode::kInvalidArgument);
  std::optional<ErrorInfo> again = GetDetail<ErrorInfo>(back);
  ASSERT_TRUE(again.has_value());
  EXPECT_EQ(again->field(), "frame.depth.width");
}

TEST(GrpcStatusTest, RenamingAnAdapterFieldErrorLeavesNoStaleDetail) {
  const absl::Status adapter =
      FieldError(absl::StatusCode::kNotFound, "map_id", "no map", "MAP_NOT_FOUND");
  EXPECT_EQ(ErrorField(adapter), "map_id");  // the same payloads core's FieldStatus carries
  const grpc::Status wire = ToGrpcStatus(WithReason(WithField(adapter, "moving_map_id"), "OTHER"));
  EXPECT_EQ(wire.error_message(), "moving_map_id: no map");
  std::optional<ErrorInfo> info = GetDetail<ErrorInfo>(wire);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->field(), "moving_map_id");
  EXPECT_EQ(info->reason(), "OTHER");
}

TEST(GrpcStatusTest, AttachDetailReplacesSameTypeAndIgnoresOk) {
  absl::Status status = absl::FailedPreconditionError("no map");
  ErrorInfo first;
  first.set_reason("A");
  AttachDetail(status, first);
  ErrorInfo second;
  second.set_reason("B");
  AttachDetail(status, second);
  EXPECT_EQ(GetDetail<ErrorInfo>(status)->reason(), "B");

  absl::Status ok = absl::OkStatus();
  AttachDetail(ok, first);
  EXPECT_TRUE(ok.ok());
}

TEST(GrpcStatusTest, NonProtoPayloadsStayLocal) {
  absl::Status status = absl::InternalError("boom");
  status.SetPayload("local/trace", absl::Cord("secret-ish"));
  const grpc::Status wire = ToGrpcStatus(status);
  EXPECT_EQ(wire.error_details().find("secret-ish"), std::string::npos);
  EXPECT_EQ(GetDetail<ErrorInfo>(wire)->reason(), "INTERNAL");
}

TEST(GrpcStatusTest, CoreFieldStatusBecomesErrorInfoWithoutStringParsing) {
  const grpc::Status wire = ToGrpcStatus(
      FieldStatus(absl::StatusCode::kNotFound, "map_id", "no such map", "MAP_NOT_FOUND"));
  EXPECT_EQ(wire.error_code(), grpc::StatusCode::NOT_FOUND);
  std::optional<ErrorInfo> info = GetDetail<ErrorInfo>(wire);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->field(), "map_id");
  EXPECT_EQ(info->reason(), "MAP_NOT_FOUND");
  // The local payloads are not sent as such.
  EXPECT_EQ(wire.error_details().find("semnav.dev/"), std::string::npos);
}

TEST(GrpcStatusTest, HugeMessagesAreCutShort) {
  const grpc::Status wire = ToGrpcStatus(absl::InvalidArgumentError(std::string(1 << 20, 'x')));
  EXPECT_LE(wire.error_message().size(), 1100u);
  EXPECT_LT(wire.error_details().size(), 1200u);
}

// A vendor's Retry-After crosses the wire in ErrorInfo.metadata and comes back as the same hint,
// next to the field and reason core named.
TEST(GrpcStatusTest, RetryAfterTravelsInErrorInfoMetadata) {
  absl::Status status = FieldStatus(absl::StatusCode::kUnavailable, "model_alias",
                                    "no backend answered", "BACKEND_UNAVAILABLE");
  SetRetryAfter(status, absl::Milliseconds(2500));
  const grpc::Status wire = ToGrpcStatus(status);
  const std::optional<ErrorInfo> info = GetDetail<ErrorInfo>(wire);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->reason(), "BACKEND_UNAVAILABLE");
  EXPECT_EQ(info->field(), "model_alias");
  EXPECT_EQ(info->metadata().at("retry_after_s"), "2.500");
  const absl::Status back = FromGrpcStatus(wire);
  EXPECT_EQ(RetryAfter(back), absl::Milliseconds(2500));
  // An attached ErrorInfo keeps its own metadata and gains the hint.
  absl::Status typed = FieldError(absl::StatusCode::kResourceExhausted, "", "rate limited", "RL");
  SetRetryAfter(typed, absl::Seconds(7));
  const std::optional<ErrorInfo> typed_info = GetDetail<ErrorInfo>(ToGrpcStatus(typed));
  EXPECT_EQ(typed_info->reason(), "RL");
  EXPECT_EQ(typed_info->metadata().at("retry_after_s"), "7.000");
  // Without a hint nothing is added.
  EXPECT_FALSE(RetryAfter(FromGrpcStatus(ToGrpcStatus(absl::UnavailableError("x")))).has_value());
}

TEST(RetryAfterTest, DeltaSecondsOnlyAndBounded) {
  EXPECT_EQ(ParseRetryAfterSeconds("120"), absl::Seconds(120));
  EXPECT_EQ(ParseRetryAfterSeconds(" 1.5 "), absl::Milliseconds(1500));
  EXPECT_FALSE(ParseRetryAfterSeconds("Wed, 21 Oct 2015 07:28:00 GMT").has_value());
  EXPECT_FALSE(ParseRetryAfterSeconds("-1").has_value());
  EXPECT_FALSE(ParseRetryAfterSeconds("nan").has_value());
  EXPECT_FALSE(ParseRetryAfterSeconds("86401").has_value());
  absl::Status ok = absl::OkStatus();
  SetRetryAfter(ok, absl::Seconds(1));
  EXPECT_FALSE(RetryAfter(ok).has_value());  // an OK status carries nothing
}

}  // namespace
}  // namespace semnav
