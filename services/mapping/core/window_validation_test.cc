#include "services/mapping/core/window_validation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace semnav::mapping {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

constexpr double kResolution = 0.05;

std::string Rejected(double min_x, double min_y, double max_x, double max_y,
                     const WindowLimits& limits = {}) {
  const absl::Status status = ValidateWindow(min_x, min_y, max_x, max_y, kResolution, limits);
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << status;
  return std::string(status.message());
}

TEST(WindowValidationTest, AcceptsAnOrdinaryRoomWindow) {
  EXPECT_TRUE(ValidateWindow(-2.0, -3.0, 8.0, 6.5, kResolution, {}).ok());
}

TEST(WindowValidationTest, NonFiniteCornersNameTheirField) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THAT(Rejected(-inf, 0, 1, 1), StartsWith("window.min.x: must be finite"));
  EXPECT_THAT(Rejected(0, std::nan(""), 1, 1), StartsWith("window.min.y: must be finite"));
  EXPECT_THAT(Rejected(0, 0, inf, 1), StartsWith("window.max.x: must be finite"));
  EXPECT_THAT(Rejected(0, 0, 1, -inf), StartsWith("window.max.y: must be finite"));
}

TEST(WindowValidationTest, HugeCoordinatesAreOutsideAnyWorldAndNotEchoed) {
  const std::string message = Rejected(0, 0, 1e300, 1);
  EXPECT_THAT(message, StartsWith("window.max.x: must be within +-100000 m"));
  EXPECT_THAT(message, Not(HasSubstr("1e+300")));
  EXPECT_THAT(Rejected(0, 0, 1e6, 1), StartsWith("window.max.x"));
}

TEST(WindowValidationTest, EmptyOrInvertedWindowsAreRejected) {
  EXPECT_THAT(Rejected(2, 0, 1, 1), StartsWith("window.max.x: must be > window.min.x"));
  EXPECT_THAT(Rejected(0, 1, 1, 1), StartsWith("window.max.y: must be > window.min.y"));
}

TEST(WindowValidationTest, CellBudgetCountsCellsAtTheGridResolution) {
  // [0, 0.999] x [0, 0.999] at 5 cm touches cells 0..19 on each axis: 400 cells.
  WindowLimits limits;
  limits.max_cells = 400;
  EXPECT_TRUE(ValidateWindow(0, 0, 0.999, 0.999, kResolution, limits).ok());
  // 1.0 m reaches cell 20: 21 x 21 = 441 > 400.
  EXPECT_THAT(Rejected(0, 0, 1.0, 1.0, limits), StartsWith("window: covers more than 400 cells"));
  // The default budget (16 Mi cells) refuses 10 km x 10 km but not 200 m x 200 m.
  EXPECT_THAT(Rejected(-5000, -5000, 5000, 5000), StartsWith("window: covers more than"));
  EXPECT_TRUE(ValidateWindow(-100, -100, 100, 100, kResolution, {}).ok());
}

}  // namespace
}  // namespace semnav::mapping
