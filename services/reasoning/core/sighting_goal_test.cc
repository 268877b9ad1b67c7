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
  std::optional<Eigen::Vector3d> sighting = NextSighting(sightings, At(0, 0), 3.0);
  ASSERT_TRUE(sighting.has_value());
  EXPECT_EQ(*sighting, Eigen::Vector3d(0, 5, 2));
  EXPECT_TRUE(StraightLookGoal(*sighting, At(0, 0), 3.0).isApprox(Eigen::Vector3d(0, 2, 1.5)));
  // Once a goal within 3 + 1 m of (0, 5) is spent, (10, 0) is next: (7, 0).
  ExplorationQuery query = At(0, 0);
  query.excluded_goals = {Eigen::Vector3d(0, 2, 1.5)};
  sighting = NextSighting(sightings, query, 3.0);
  ASSERT_TRUE(sighting.has_value());
  EXPECT_EQ(*sighting, Eigen::Vector3d(10, 0, 0));
  EXPECT_TRUE(StraightLookGoal(*sighting, query, 3.0).isApprox(Eigen::Vector3d(7, 0, 1.5)));
  // Both looked at: planning's turn.
  query.excluded_goals.push_back(Eigen::Vector3d(6.5, 0.5, 1.5));  // 3.54 m from (10, 0)
  EXPECT_FALSE(NextSighting(sightings, query, 3.0).has_value());
  EXPECT_FALSE(NextSighting({}, At(0, 0), 3.0).has_value());
}

TEST(SightingGoalTest, ARobotAlreadyThatCloseGetsItsOwnPositionToSpend) {
  // 2 m from the sighting: the goal is where the robot stands (the executor spends it at once,
  // and the spent goal marks the sighting looked at).
  const Eigen::Vector3d goal = StraightLookGoal({4, 3, 0}, At(4, 1, 2.0), 3.0);
  EXPECT_EQ(goal, Eigen::Vector3d(4, 1, 2.0));
  ExplorationQuery query = At(4, 1, 2.0);
  query.excluded_goals = {goal};
  EXPECT_FALSE(NextSighting({{4, 3, 0}}, query, 3.0).has_value());
}

TEST(SightingGoalTest, ALookCutShortBeforeAWallIsSpentByItsOwnGoal) {
  // Planning cut the look at (10, 0) short before a wall: the goal (2, 0) is 8 m from the
  // sighting, beyond 3 + 1 m, so only the look's record marks the sighting looked at once (2, 0)
  // is spent (within the 1 m radius: (2.5, 0.5) is 0.71 m from it).
  const std::vector<Eigen::Vector3d> sightings = {{10, 0, 0}};
  const std::vector<SightingLook> looks = {{{10, 0, 0}, {2, 0, 1.5}}};
  ExplorationQuery query = At(0, 0);
  query.excluded_goals = {Eigen::Vector3d(2.5, 0.5, 1.5)};
  EXPECT_TRUE(NextSighting(sightings, query, 3.0).has_value());  // without the record
  EXPECT_FALSE(NextSighting(sightings, query, 3.0, looks).has_value());
  // A goal given for another sighting does not spend this one.
  const std::vector<SightingLook> other = {{{0, 10, 0}, {2, 0, 1.5}}};
  EXPECT_TRUE(NextSighting(sightings, query, 3.0, other).has_value());
}

}  // namespace
}  // namespace semnav::reasoning
