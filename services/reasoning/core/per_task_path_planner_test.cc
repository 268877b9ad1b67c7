#include "services/reasoning/core/per_task_path_planner.h"

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

class CountingExplorer final : public ExplorationService {
 public:
  absl::StatusOr<Eigen::Vector3d> SelectGoal(const ExplorationQuery&,
                                             std::optional<ExplorationStrategy>,
                                             const ExplorationContext&) override {
    ++calls;
    return Eigen::Vector3d(20, 20, 1.5);
  }
  int calls = 0;
};

TEST(PerTaskPathPlannerTest, APlaceTheModelSawTheTargetAtIsLookedAtBeforePlanningsGoal) {
  CountingExplorer explorer;
  ExplorationContext context;
  context.eroi_sightings = {Eigen::Vector3d(10, 0, 0)};
  context.eroi_inspect_distance_m = 3.0;
  PerTaskPathPlanner planner(nullptr, &explorer, ExplorationStrategy::kEroiUtility,
                             [&] { return context; });
  ExplorationQuery query;
  query.pose.position = Eigen::Vector3d(0, 0, 1.5);
  query.excluded_radius_m = 1.0;
  absl::StatusOr<Eigen::Vector3d> goal = planner.ExplorationGoal(query);
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(7, 0, 1.5))) << goal->transpose();
  EXPECT_EQ(explorer.calls, 0);
  // Looked at (its goal spent): planning answers.
  query.excluded_goals = {*goal};
  goal = planner.ExplorationGoal(query);
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_EQ(*goal, Eigen::Vector3d(20, 20, 1.5));
  EXPECT_EQ(explorer.calls, 1);
  // Inspect distance 0: sightings are evidence only, as in the seed.
  context.eroi_inspect_distance_m = 0.0;
  query.excluded_goals.clear();
  EXPECT_EQ(*planner.ExplorationGoal(query), Eigen::Vector3d(20, 20, 1.5));
  EXPECT_EQ(explorer.calls, 2);
}

}  // namespace
}  // namespace semnav::reasoning
