#include "services/reasoning/core/sighting_goal.h"

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

ExplorationQuery At(double x, double y, double z = 1.5) {
  ExplorationQuery query;
  query.pose.position = Eigen::Vector3d(x, y, z);
  query.excluded_radius_m = 1.0;
  return query;
}

TEST(SightingGoalTest, TheNearestSightingIsLookedAtFromTheInspectDistanceByHand) {
  const std::vector<Eigen::Vector3d> sightings = {{10, 0, 0}, {0, 5, 2}};
  // (0, 5) is 5 m away, (10, 0) 10 m: 3 m short of (0, 5) on the line from the robot is (0, 2),
  // at the robot's altitude.
  std::optional<Eigen::Vector3d> goal = SightingGoal(sightings, At(0, 0), 3.0);
  ASSERT_TRUE(goal.has_value());
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(0, 2, 1.5))) << goal->transpose();
  // Once a goal within 3 + 1 m of (0, 5) is spent, (10, 0) is next: (7, 0).
  ExplorationQuery query = At(0, 0);
  query.excluded_goals = {Eigen::Vector3d(0, 2, 1.5)};
  goal = SightingGoal(sightings, query, 3.0);
  ASSERT_TRUE(goal.has_value());
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(7, 0, 1.5))) << goal->transpose();
  // Both looked at: planning's turn.
  query.excluded_goals.push_back(Eigen::Vector3d(6.5, 0.5, 1.5));  // 3.54 m from (10, 0)
  EXPECT_FALSE(SightingGoal(sightings, query, 3.0).has_value());
  EXPECT_FALSE(SightingGoal({}, At(0, 0), 3.0).has_value());
}

TEST(SightingGoalTest, ARobotAlreadyThatCloseGetsItsOwnPositionToSpend) {
  // 2 m from the sighting: the goal is where the robot stands (the executor spends it at once,
  // and the spent goal marks the sighting looked at).
  const std::optional<Eigen::Vector3d> goal = SightingGoal({{4, 3, 0}}, At(4, 1, 2.0), 3.0);
  ASSERT_TRUE(goal.has_value());
  EXPECT_EQ(*goal, Eigen::Vector3d(4, 1, 2.0));
  ExplorationQuery query = At(4, 1, 2.0);
  query.excluded_goals = {*goal};
  EXPECT_FALSE(SightingGoal({{4, 3, 0}}, query, 3.0).has_value());
}

}  // namespace
}  // namespace semnav::reasoning
