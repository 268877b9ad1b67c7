#include "services/common/status/field_error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "services/common/status/value_checks.h"

namespace semnav {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(FieldErrorTest, CarriesFieldAndReasonBesideTheMessage) {
  const absl::Status status =
      FieldStatus(absl::StatusCode::kFailedPrecondition, "lease_id", "expired", "LEASE_EXPIRED");
  EXPECT_EQ(status.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(status.message(), "lease_id: expired");
  EXPECT_EQ(ErrorField(status), "lease_id");
  EXPECT_EQ(ErrorReason(status), "LEASE_EXPIRED");
  EXPECT_EQ(ErrorReason(InvalidField("pose.x", "bad")), "FIELD_INVALID");
  EXPECT_FALSE(ErrorField(absl::InternalError("x")).has_value());
}

TEST(FieldErrorTest, WithFieldRenamesTheFieldAndKeepsCodeAndReason) {
  const absl::Status core =
      FieldStatus(absl::StatusCode::kNotFound, "map_id", "no map \"a\"", "MAP_NOT_FOUND");
  const absl::Status renamed = WithField(core, "reference_map_id");
  EXPECT_EQ(renamed.code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(renamed.message(), "reference_map_id: no map \"a\"");
  EXPECT_EQ(ErrorField(renamed), "reference_map_id");
  EXPECT_EQ(ErrorReason(renamed), "MAP_NOT_FOUND");
  // An error that named no field gets one in front of its whole message.
  const absl::Status unnamed = WithField(absl::DataLossError("file x is corrupt"), "map_id");
  EXPECT_EQ(unnamed.message(), "map_id: file x is corrupt");
  EXPECT_EQ(ErrorField(unnamed), "map_id");
  EXPECT_EQ(ErrorReason(unnamed), std::nullopt);
}

TEST(FieldErrorTest, DefaultReasonNeverOverridesTheOneCoreChose) {
  EXPECT_EQ(ErrorReason(WithDefaultReason(InvalidField("top_k", "must be > 0"), "STEP_FAILED")),
            "FIELD_INVALID");
  const absl::Status plain =
      WithDefaultReason(absl::NotFoundError("no consistent match"), "STEP_FAILED");
  EXPECT_EQ(ErrorReason(plain), "STEP_FAILED");
  EXPECT_EQ(ErrorField(plain), std::nullopt);
  EXPECT_EQ(ErrorReason(WithReason(InvalidField("a", "b"), "OTHER")), "OTHER");
  EXPECT_TRUE(WithReason(absl::OkStatus(), "OTHER").ok());
}

TEST(FieldErrorTest, PreviewKeepsAShortEscapedPrefixAndTheSize) {
  EXPECT_EQ(Preview("robot-1"), "robot-1");
  EXPECT_EQ(Preview(std::string(100, 'a'), 4), "aaaa... (100 bytes)");
  EXPECT_EQ(Preview(std::string("a\nb\0c", 5)), "a\\nb\\000c");
}

TEST(ValueChecksTest, NumbersMustBeFiniteAndSane) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(CheckFinite(1e300, "x").ok());
  EXPECT_EQ(ErrorField(CheckFinite(std::nan(""), "pose.position.x")), "pose.position.x");
  EXPECT_EQ(CheckFinite(-inf, "v").code(), absl::StatusCode::kInvalidArgument);
  EXPECT_TRUE(CheckMagnitude(-1e5, "x", kMaxCoordinateM).ok());
  EXPECT_THAT(std::string(CheckMagnitude(1e300, "goal.x", kMaxCoordinateM).message()),
              ::testing::StartsWith("goal.x: must be within +-100000"));
  EXPECT_TRUE(CheckRange(0.5, "score", 0, 1).ok());
  EXPECT_FALSE(CheckRange(1.5, "score", 0, 1).ok());
  EXPECT_FALSE(CheckRange(std::nan(""), "score", 0, 1).ok());
}

TEST(ValueChecksTest, PointsNameTheAxisThatIsWrong) {
  EXPECT_TRUE(CheckPoint(1, -2, 3, "pose.position", kMaxCoordinateM).ok());
  EXPECT_EQ(ErrorField(CheckPoint(std::nan(""), 0, 0, "pose.position", kMaxCoordinateM)),
            "pose.position.x");
  EXPECT_EQ(ErrorField(CheckPoint(0, 1e300, 0, "near", kMaxCoordinateM)), "near.y");
  EXPECT_EQ(ErrorField(CheckPoint(0, 0, -2e5, "goal", kMaxCoordinateM)), "goal.z");
}

TEST(ValueChecksTest, LongStringsAreRefusedWithoutEchoingThem) {
  EXPECT_TRUE(CheckLength(std::string(kMaxIdBytes, 'r'), "robot_id", kMaxIdBytes).ok());
  const absl::Status status = CheckLength(std::string(1 << 20, 'r'), "robot_id", kMaxIdBytes);
  EXPECT_EQ(ErrorField(status), "robot_id");
  EXPECT_LT(status.message().size(), 160u);
  EXPECT_THAT(std::string(status.message()), HasSubstr("1048576 bytes"));
  EXPECT_THAT(std::string(status.message()), Not(HasSubstr(std::string(64, 'r'))));
  EXPECT_FALSE(CheckCount(1001, "detections", 1000).ok());
}

}  // namespace
}  // namespace semnav
