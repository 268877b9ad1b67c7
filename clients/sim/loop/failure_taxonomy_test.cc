#include "clients/sim/loop/failure_taxonomy.h"

#include <gtest/gtest.h>

namespace semnav::sim::loop {
namespace {

namespace api = semnav::reasoning::v1;

// A 250 s episode in a 20 x 20 m world that ran out of budget: the robot drove east at 0.2 m/s
// and never saw the target, which stayed 10 m away or more.
EpisodeTrace Exploring() {
  EpisodeTrace trace;
  trace.bounds_min = Eigen::Vector2d(0, 0);
  trace.bounds_max = Eigen::Vector2d(20, 20);
  for (int step = 1; step <= 500; ++step) {
    const double t = 0.5 * step;
    trace.samples.push_back(
        TraceSample{t, Eigen::Vector2d(0.2 * t / 2.5, 1.0), 10.0 + t / 100.0, false});
  }
  trace.task.push_back(
      TaskChange{0.0, api::TASK_STATUS_RUNNING, "exploring", "exploring for the target"});
  trace.budget_spent = true;
  trace.end_s = 250.0;
  return trace;
}

TaskChange Failed(double t, const std::string& reason) {
  return TaskChange{t, api::TASK_STATUS_FAILED, "done", reason};
}

TEST(SimFailureTaxonomyTest, SuccessHasNoCause) {
  EpisodeTrace trace = Exploring();
  trace.success = true;
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kNone);
  EXPECT_EQ(FailureCauseName(FailureCause::kNone), "");
}

TEST(SimFailureTaxonomyTest, BudgetSpentExploringIsTheFallback) {
  EXPECT_EQ(ClassifyFailure(Exploring()), FailureCause::kBudgetSpentExploring);
  EXPECT_EQ(FailureCauseName(FailureCause::kBudgetSpentExploring), "budget_spent_exploring");
}

TEST(SimFailureTaxonomyTest, RefusedInstruction) {
  EpisodeTrace trace;
  trace.instruction_refused = true;
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kRefusedInstruction);
}

TEST(SimFailureTaxonomyTest, DeclaredStopOutsideTheRegion) {
  EpisodeTrace trace = Exploring();
  trace.stop_declared = true;
  trace.budget_spent = false;
  trace.samples.back().target_distance_m = 0.6;  // e.g. on the wrong side of a wall
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kStoppedOutsideRegion);
  trace.samples.back().target_distance_m = 6.0;  // stopped at something else
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kWrongObjectVerified);
}

TEST(SimFailureTaxonomyTest, ReachedButNeverStopped) {
  EpisodeTrace trace = Exploring();
  trace.target_first_seen_s = 100.0;
  trace.samples[300].in_success_region = true;
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kReachedNeverStopped);
  // In the region without having seen the target: it drove past unaware.
  trace.target_first_seen_s.reset();
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kBudgetSpentExploring);
}

TEST(SimFailureTaxonomyTest, GoalsOutsideTheMap) {
  EpisodeTrace trace = Exploring();
  trace.goals.push_back(NavigateGoal{10.0, Eigen::Vector2d(5, 5)});
  trace.goals.push_back(NavigateGoal{20.0, Eigen::Vector2d(25, 5)});
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kBudgetSpentExploring);  // one is not enough
  trace.feedback.push_back(
      FeedbackEvent{21.0, api::FEEDBACK_KIND_FAILED, "goal (25, 5) is outside the grid"});
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kGoalOutsideMap);
}

TEST(SimFailureTaxonomyTest, CollisionLoop) {
  EpisodeTrace trace = Exploring();
  for (int i = 0; i < 3; ++i) {
    trace.feedback.push_back(
        FeedbackEvent{10.0 * i, api::FEEDBACK_KIND_BLOCKED, "collision with crate"});
  }
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kBudgetSpentExploring);
  trace.feedback.push_back(FeedbackEvent{40.0, api::FEEDBACK_KIND_BLOCKED, "collision with wall"});
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kCollisionLoop);
  // The task giving up on a blocked robot is the same cause with fewer blocks.
  EpisodeTrace gave_up = Exploring();
  gave_up.task.push_back(Failed(80.0, "gave up after 3 re-plans: robot blocked"));
  EXPECT_EQ(ClassifyFailure(gave_up), FailureCause::kCollisionLoop);
}

TEST(SimFailureTaxonomyTest, NoPath) {
  EpisodeTrace trace = Exploring();
  for (int i = 0; i < 3; ++i) {
    trace.task.push_back(TaskChange{10.0 * i + 1, api::TASK_STATUS_RUNNING, "exploring",
                                    "no path to the exploration goal: goal unreachable"});
    trace.task.push_back(
        TaskChange{10.0 * i + 2, api::TASK_STATUS_RUNNING, "exploring", "exploring"});
  }
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kNoPath);
}

TEST(SimFailureTaxonomyTest, StuckInAStateForTheConfiguredTime) {
  EpisodeTrace trace = Exploring();
  // From t = 31 s the robot turns on the spot in "verifying" until the budget ends (office_03).
  for (TraceSample& s : trace.samples) {
    if (s.time_s >= 31.0) s.position = Eigen::Vector2d(2.48, 1.0);
  }
  trace.task.push_back(
      TaskChange{31.0, api::TASK_STATUS_RUNNING, "verifying", "turning to face the target"});
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kStuckInState);
  // Within 1 m of that spot from t = 18.5 s (0.08 m/s covers the last metre in 12.5 s) to the
  // end at 250 s: 231.5 s without progress, stuck under a 230 s threshold, not under 240 s.
  FailureTaxonomyConfig config;
  config.stuck_s = 230.0;
  EXPECT_EQ(ClassifyFailure(trace, config), FailureCause::kStuckInState);
  config.stuck_s = 240.0;
  EXPECT_EQ(ClassifyFailure(trace, config), FailureCause::kBudgetSpentExploring);
}

TEST(SimFailureTaxonomyTest, SlowSteadyProgressIsNotStuck) {
  // Progress is leaving a 1 m disc within 60 s: 0.02 m/s does, 0.015 m/s does not.
  EpisodeTrace trace = Exploring();
  for (TraceSample& s : trace.samples)
    s.position = Eigen::Vector2d(0.02 * s.time_s, 1.0);  // 1 m per 50 s
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kBudgetSpentExploring);
  for (TraceSample& s : trace.samples)
    s.position = Eigen::Vector2d(0.015 * s.time_s, 1.0);  // 1 m per 67 s
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kStuckInState);
}

TEST(SimFailureTaxonomyTest, SeenButNeverApproached) {
  EpisodeTrace trace = Exploring();
  trace.target_first_seen_s = 120.0;
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kSeenNeverApproached);
}

TEST(SimFailureTaxonomyTest, TaskGaveUpSearchingOrFailedOtherwise) {
  EpisodeTrace trace = Exploring();
  trace.budget_spent = false;
  trace.task.push_back(Failed(90.0, "target not found after 15 exploration goals"));
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kGaveUpSearching);
  trace.task.back().reason = "refused to send the robot a command: speed too high";
  EXPECT_EQ(ClassifyFailure(trace), FailureCause::kTaskFailed);
}

}  // namespace
}  // namespace semnav::sim::loop
