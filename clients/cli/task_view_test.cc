#include "clients/cli/task_view.h"

#include "gtest/gtest.h"

namespace semnav::cli {
namespace {

reasoning_api::TaskSnapshot SearchTask() {
  reasoning_api::TaskSnapshot task;
  task.set_task_id("task-7");
  task.set_status(reasoning_api::TASK_STATUS_RUNNING);
  task.set_progress(0.25);
  task.set_current_subgoal(1);
  task.set_phase("exploring");
  reasoning_api::Subgoal* navigate = task.add_subgoals();
  navigate->set_type(reasoning_api::SUBGOAL_TYPE_NAVIGATE);
  navigate->mutable_target()->set_name("kitchen");
  reasoning_api::Subgoal* find = task.add_subgoals();
  find->set_type(reasoning_api::SUBGOAL_TYPE_FIND);
  find->mutable_target()->set_name("cup");
  find->mutable_target()->add_colours("red");
  find->mutable_target()->set_relation("near");
  find->mutable_target()->set_anchor("door");
  task.add_subgoals()->set_type(reasoning_api::SUBGOAL_TYPE_APPROACH);
  task.add_subgoals()->set_type(reasoning_api::SUBGOAL_TYPE_VERIFY);
  return task;
}

TEST(TaskViewTest, ProgressShowsTheActiveStepWithItsTarget) {
  const TaskProgress progress = ToProgress(SearchTask());
  EXPECT_EQ(progress.status, "RUNNING");
  EXPECT_EQ(progress.step, "FIND red cup near door");
  EXPECT_EQ(progress.subgoal_count, 4);
  EXPECT_EQ(FormatProgressLine(progress, 4),
            "task-7  RUNNING    [#---]   25%  step 2/4 FIND red cup near door  exploring");
}

TEST(TaskViewTest, FinishedTaskHasNoActiveStep) {
  reasoning_api::TaskSnapshot task = SearchTask();
  task.set_status(reasoning_api::TASK_STATUS_SUCCEEDED);
  task.set_current_subgoal(4);
  EXPECT_EQ(ToProgress(task).step, "");
  EXPECT_TRUE(IsFinished(task.status()));
  EXPECT_FALSE(IsFinished(reasoning_api::TASK_STATUS_PAUSED));
}

TEST(TaskViewTest, FollowedTaskOutcomeIsTheExitCode) {
  EXPECT_EQ(ExitCodeForTask(reasoning_api::TASK_STATUS_SUCCEEDED), ExitCode::kOk);
  EXPECT_EQ(ToInt(ExitCodeForTask(reasoning_api::TASK_STATUS_FAILED)), 10);
  EXPECT_EQ(ToInt(ExitCodeForTask(reasoning_api::TASK_STATUS_CANCELLED)), 11);
  EXPECT_EQ(ExitCodeForTask(reasoning_api::TASK_STATUS_RUNNING), ExitCode::kError);
}

TEST(TaskViewTest, DescriptionMarksDoneActiveAndTheResolvedTarget) {
  reasoning_api::TaskSnapshot task = SearchTask();
  task.mutable_target()->set_object_id(12);
  task.mutable_target()->set_label("cup");
  task.mutable_target()->mutable_position()->set_x(1.5);
  task.mutable_target()->set_confidence(0.875);
  task.mutable_target()->set_path(reasoning_api::RESOLUTION_PATH_FAST);
  const std::string text = DescribeTask(task);
  EXPECT_NE(text.find("target:       object 12 'cup' at (1.50, 0.00, 0.00) confidence 0.88 FAST"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("1  NAVIGATE kitchen        done"), std::string::npos) << text;
  EXPECT_NE(text.find("2  FIND red cup near door  active"), std::string::npos) << text;
}

}  // namespace
}  // namespace semnav::cli
