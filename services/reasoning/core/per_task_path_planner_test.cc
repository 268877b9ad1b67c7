#include "services/reasoning/core/per_task_path_planner.h"

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

class CountingExplorer final : public ExplorationService {
 public:
  absl::StatusOr<Eigen::Vector3d> SelectGoal(const ExplorationQuery&,
                                             std::optional<ExplorationStrategy>,
                                             const ExplorationContext& context) override {
    ++calls;
    looks.push_back(context.look_at);
    if (context.look_at.has_value()) return look_answer;
    return Eigen::Vector3d(20, 20, 1.5);
  }
  int calls = 0;
  std::vector<std::optional<Eigen::Vector3d>> looks;
  absl::StatusOr<Eigen::Vector3d> look_answer = Eigen::Vector3d(4, 0, 1.5);
};

ExplorationQuery AtOrigin() {
  ExplorationQuery query;
  query.pose.position = Eigen::Vector3d(0, 0, 1.5);
  query.excluded_radius_m = 1.0;
  return query;
}

TEST(PerTaskPathPlannerTest, APlaceTheModelSawTheTargetAtIsLookedAtFromWherePlanningSays) {
  CountingExplorer explorer;
  ExplorationContext context;
  context.eroi_sightings = {Eigen::Vector3d(10, 0, 0)};
  context.eroi_inspect_distance_m = 3.0;
  PerTaskPathPlanner planner(nullptr, &explorer, ExplorationStrategy::kEroiUtility,
                             [&] { return context; });
  ExplorationQuery query = AtOrigin();
  // Planning is asked where to look at (10, 0) from; it answers (4, 0) (a wall cut the look short
  // of the straight line's (7, 0)).
  absl::StatusOr<Eigen::Vector3d> goal = planner.ExplorationGoal(query);
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_EQ(*goal, Eigen::Vector3d(4, 0, 1.5));
  ASSERT_EQ(explorer.looks.size(), 1u);
  EXPECT_EQ(explorer.looks[0], Eigen::Vector3d(10, 0, 0));
  // Looked at (its goal spent, 6 m from the sighting): planning's exploration goal.
  query.excluded_goals = {*goal};
  goal = planner.ExplorationGoal(query);
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_EQ(*goal, Eigen::Vector3d(20, 20, 1.5));
  ASSERT_EQ(explorer.looks.size(), 2u);
  EXPECT_FALSE(explorer.looks[1].has_value());
  // Inspect distance 0: sightings are evidence only, as in the seed.
  context.eroi_inspect_distance_m = 0.0;
  query.excluded_goals.clear();
  EXPECT_EQ(*planner.ExplorationGoal(query), Eigen::Vector3d(20, 20, 1.5));
  EXPECT_EQ(explorer.calls, 3);
}

TEST(PerTaskPathPlannerTest, APlanningWithoutALookAnswerLeavesTheStraightLine) {
  CountingExplorer explorer;
  explorer.look_answer = absl::NotFoundError("no look");
  ExplorationContext context;
  context.eroi_sightings = {Eigen::Vector3d(10, 0, 0)};
  context.eroi_inspect_distance_m = 3.0;
  PerTaskPathPlanner planner(nullptr, &explorer, ExplorationStrategy::kEroiUtility,
                             [&] { return context; });
  absl::StatusOr<Eigen::Vector3d> goal = planner.ExplorationGoal(AtOrigin());
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(7, 0, 1.5))) << goal->transpose();
  // A planning that is gone pauses the task instead (UNAVAILABLE passes through).
  explorer.look_answer = absl::UnavailableError("planning down");
  EXPECT_TRUE(absl::IsUnavailable(planner.ExplorationGoal(AtOrigin()).status()));
}

}  // namespace
}  // namespace semnav::reasoning
