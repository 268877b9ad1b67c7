// The gateway's task registry: ids count up across restores, listing is submission order, and
// a view differs in content only by what an operator would see change.
#include "services/reasoning/core/task_registry.h"

#include "gtest/gtest.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

class NoPlanner : public PathPlanner {
 public:
  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery&) override {
    return std::vector<Eigen::Vector3d>{};
  }
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery&) override {
    return absl::NotFoundError("none");
  }
};

class TaskRegistryTest : public ::testing::Test {
 protected:
  TaskRecord& Add(const std::string& robot_id) { return AddTo(registry_, robot_id); }
  TaskRecord& AddTo(TaskRegistry& registry, const std::string& robot_id) {
    TaskRecord& task = registry.Create();
    task.robot_id = robot_id;
    Subgoal wait;
    wait.type = SubgoalType::kWait;
    task.executor = std::make_unique<TaskExecutor>("wait", std::vector<Subgoal>{wait}, &resolver_,
                                                   &planner_, nullptr, ExecutorConfig{});
    return task;
  }

  NoPlanner planner_;
  FastResolver resolver_{&ShippedLexicon(), FastResolverConfig{}};
  TaskRegistry registry_;
};

TEST_F(TaskRegistryTest, IdsCountUpAndContinueAfterARestoredJournal) {
  EXPECT_EQ(Add("r1").task_id, "task-1");
  EXPECT_EQ(Add("r1").task_id, "task-2");
  registry_.Restore("task-7", 8);  // a journal saved before the restart said the next is 8
  EXPECT_EQ(registry_.next_number(), 8u);
  EXPECT_EQ(Add("r1").task_id, "task-8");
  registry_.Restore("task-3", 4);  // an older next number never goes back
  EXPECT_EQ(Add("r1").task_id, "task-9");
  EXPECT_NE(registry_.Find("task-7"), nullptr);
  EXPECT_EQ(registry_.Find("task-99"), nullptr);
}

TEST_F(TaskRegistryTest, SelectIsSubmissionOrderNotStringOrder) {
  for (int i = 0; i < 10; ++i) Add(i % 2 == 0 ? "even" : "odd");
  std::vector<std::string> ids;
  for (const TaskRecord* task : registry_.Select("", false)) ids.push_back(task->task_id);
  ASSERT_EQ(ids.size(), 10u);
  EXPECT_EQ(ids[8], "task-9");
  EXPECT_EQ(ids[9], "task-10");  // "task-10" < "task-2" as strings
  std::vector<std::string> odd;
  for (const TaskRecord* task : registry_.Select("odd", false)) odd.push_back(task->task_id);
  EXPECT_EQ(odd, (std::vector<std::string>{"task-2", "task-4", "task-6", "task-8", "task-10"}));

  registry_.Find("task-4")->executor->Cancel("operator");
  EXPECT_EQ(registry_.Select("odd", true).size(), 4u);
}

TEST_F(TaskRegistryTest, ViewsDifferInContentOnlyByWhatAnOperatorSees) {
  TaskRecord& task = Add("r1");
  const TaskView first = ViewOf(task, ExplorationStrategy::kSemanticFrontier);
  EXPECT_TRUE(first.pending);  // not started: its robot has no session yet
  EXPECT_EQ(first.progress, 0.0);

  TaskView bumped = first;
  bumped.revision = 5;
  bumped.updated = first.updated + absl::Seconds(3);
  EXPECT_TRUE(SameContent(first, bumped));

  task.started = true;
  EXPECT_FALSE(SameContent(
      first, ViewOf(task, ExplorationStrategy::kSemanticFrontier)));  // PENDING -> RUNNING
  EXPECT_FALSE(SameContent(first, ViewOf(task, std::nullopt)));       // strategy no longer reported
  task.started = false;
  task.executor->Cancel("operator");
  const TaskView cancelled = ViewOf(task, ExplorationStrategy::kSemanticFrontier);
  EXPECT_EQ(cancelled.state, TaskState::kCancelled);
  EXPECT_FALSE(cancelled.pending);
  EXPECT_FALSE(SameContent(first, cancelled));
  EXPECT_FALSE(SameContent(TaskView{}, first));  // nothing published yet
}

TEST_F(TaskRegistryTest, CreateForgetsTheOldestFinishedTasksBeyondTheKeptCount) {
  TaskRegistry registry(2);
  for (int i = 0; i < 5; ++i) AddTo(registry, "r1");  // task-1 .. task-5
  for (const char* id : {"task-1", "task-2", "task-3", "task-4"}) {
    registry.Find(id)->executor->Cancel("done");
  }
  registry.Find("task-1")->in_remote_call = true;  // its record is in use: kept
  AddTo(registry, "r1");                           // task-6; 4 finished, 1 in use, keep 2
  EXPECT_NE(registry.Find("task-1"), nullptr);
  EXPECT_EQ(registry.Find("task-2"), nullptr);  // the oldest free finished one goes
  EXPECT_NE(registry.Find("task-3"), nullptr);
  EXPECT_NE(registry.Find("task-4"), nullptr);
  EXPECT_NE(registry.Find("task-5"), nullptr);  // running tasks are never forgotten
  registry.Find("task-1")->in_remote_call = false;
  AddTo(registry, "r1");  // task-7: now task-1 goes too
  std::vector<std::string> ids;
  for (const TaskRecord* task : registry.Select("", false)) ids.push_back(task->task_id);
  EXPECT_EQ(ids, (std::vector<std::string>{"task-3", "task-4", "task-5", "task-6", "task-7"}));
  EXPECT_EQ(AddTo(registry, "r1").task_id, "task-8");  // ids never go back
}

// Regression (50-robot fleet, 300 s): task-213 ran while 300 later tasks came and went; by
// submission order it was forgotten as it ended, and its operator's GetTask found nothing.
TEST_F(TaskRegistryTest, ALongTaskThatEndsLastIsKeptAndTheLongestEndedGoes) {
  TaskRegistry registry(2);
  const absl::Time t0 = absl::FromUnixSeconds(1000);
  AddTo(registry, "long");       // task-1: still running
  for (int i = 0; i < 3; ++i) {  // task-2 .. task-4 end at t0 + 1, 2, 3 s
    TaskRecord& task = AddTo(registry, "r1");
    task.executor->Cancel("done");
    task.updated = t0 + absl::Seconds(1 + i);
  }
  TaskRecord& long_task = *registry.Find("task-1");
  long_task.executor->Cancel("done");
  long_task.updated = t0 + absl::Seconds(10);  // the last to end
  AddTo(registry, "r1");                       // task-5: keep 2 of the 4 finished
  EXPECT_NE(registry.Find("task-1"), nullptr);
  EXPECT_EQ(registry.Find("task-2"), nullptr);
  EXPECT_EQ(registry.Find("task-3"), nullptr);
  EXPECT_NE(registry.Find("task-4"), nullptr);
}

TEST_F(TaskRegistryTest, KeepingNoFinishedTaskForgetsEachOneAtTheNextSubmission) {
  TaskRegistry registry(0);
  AddTo(registry, "r1").executor->Cancel("done");
  AddTo(registry, "r1");
  EXPECT_EQ(registry.Find("task-1"), nullptr);
  EXPECT_NE(registry.Find("task-2"), nullptr);
}

}  // namespace
}  // namespace semnav::reasoning
