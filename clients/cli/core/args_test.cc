#include "clients/cli/core/args.h"

#include "gtest/gtest.h"

namespace semnav::cli {
namespace {

TEST(ArgsTest, PointsNumbersAndSeconds) {
  absl::StatusOr<Point2> point = ParsePoint("from", "1.5,-2");
  ASSERT_TRUE(point.ok());
  EXPECT_DOUBLE_EQ(point->x, 1.5);
  EXPECT_DOUBLE_EQ(point->y, -2.0);
  EXPECT_DOUBLE_EQ(*ParseNumber("robot-radius", "0.25", 0.0), 0.25);
  EXPECT_EQ(*ParseCount("count", "3", 1), 3);
  EXPECT_EQ(*ParseSeconds("deadline", "2.5"), absl::Milliseconds(2500));
  EXPECT_EQ(*ParseChoice("planner", "astar", {"jps", "astar"}), 1u);
}

TEST(ArgsTest, MalformedValuesNameTheFlag) {
  absl::Status bad_point = ParsePoint("to", "3").status();
  EXPECT_EQ(bad_point.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(bad_point.message(), "--to: '3' is not a point X,Y in metres");
  EXPECT_FALSE(ParsePoint("to", "1,nan").ok());
  EXPECT_FALSE(ParseNumber("robot-radius", "-1", 0.0).ok());
  EXPECT_FALSE(ParseCount("count", "0", 1).ok());
  EXPECT_FALSE(ParseSeconds("deadline", "0").ok());
  EXPECT_EQ(ParseChoice("planner", "dijkstra", {"jps", "astar"}).status().message(),
            "--planner: 'dijkstra' is not one of jps, astar");
}

}  // namespace
}  // namespace semnav::cli
