// The gateway's tasks as plain C++ (issue 18, item 5): each task's executor with its planner,
// EROI search and model-call economy, the bookkeeping the operator API reports, and the
// registry that numbers and lists them. The server converts a TaskView to the API once
// (proto_convert); the hub coordinates tasks with robots, sessions and remote calls.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/time/time.h"
#include "services/reasoning/core/eroi_search.h"
#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/exploration_strategy.h"
#include "services/reasoning/core/model_call_policy.h"
#include "services/reasoning/core/navigation_interfaces.h"
#include "services/reasoning/core/subgoal.h"
#include "services/reasoning/core/task_executor.h"

namespace semnav::reasoning {

// What an operator sees of a task (the API's TaskSnapshot).
struct TaskView {
  std::string task_id;  // empty = nothing published yet
  std::string robot_id;
  std::string instruction;
  TaskState state = TaskState::kRunning;
  bool pending = false;  // running but not started: its robot has no session yet
  uint64_t revision = 0;
  std::vector<Subgoal> subgoals;
  int current_subgoal = 0;
  std::string phase;
  std::string reason;
  std::optional<LocatedTarget> target;
  std::vector<Eigen::Vector3d> path;
  double progress = 0.0;  // finished subgoals / subgoals, in [0, 1]
  std::string decomposition_source;
  int replans = 0;
  int explore_goals = 0;
  int model_requests = 0;
  int model_calls = 0;
  std::optional<ExplorationStrategy>
      exploration_strategy;  // nullopt = not reported (no planning service)
  std::optional<SearchArea> search_area;
  absl::Time created;
  absl::Time updated;
};

// True when `a` and `b` differ only in revision and update time: nothing to publish.
bool SameContent(const TaskView& a, const TaskView& b);

struct TaskRecord {
  std::string task_id;
  std::string robot_id;
  std::string instruction;
  std::string source;                           // decomposition source: "rules" or "model"
  std::optional<ExplorationStrategy> strategy;  // the operator's; nullopt = the configured default
  std::unique_ptr<PathPlanner> planner;         // before the executor, which refers to it
  std::unique_ptr<TaskExecutor> executor;
  uint64_t executor_generation = 0;        // bumped when the model's plan replaces the executor
  std::optional<uint64_t> graph_revision;  // scene graph revision the executor was last given
  int model_calls = 0;
  std::unique_ptr<EroiSearch> eroi;       // EROI_UTILITY tasks with a configured search volume
  std::optional<SearchArea> search_area;  // the operator's; unset = the whole map
  bool vision_busy = false;               // a VLM call of the EROI search is running
  ModelCallPolicy calls;  // call economy: new views, back-off, budget, slow-path cache
  bool started = false;
  bool paused_by_session = false;
  bool resume_on_state =
      false;  // restored after a gateway crash: resumes on the robot's next state
  // The executor is inside a remote (planning) call with the hub's lock released: nothing else
  // may enter it until the call ends; readers use `published`.
  bool in_remote_call = false;
  uint64_t revision = 0;
  absl::Time created;
  absl::Time updated;
  TaskView published;  // the last view sent to watchers
};

// The task's view now; `exploration_strategy` is reported as given (nullopt = none).
TaskView ViewOf(const TaskRecord& task, std::optional<ExplorationStrategy> exploration_strategy);

class TaskRegistry {
 public:
  // Finished tasks kept for GetTask/ListTasks (gateway key `keep_finished_tasks`): a ground
  // station left running for days would otherwise keep every task it ever ran (issue 18).
  static constexpr std::size_t kDefaultKeepFinished = 256;

  explicit TaskRegistry(std::size_t keep_finished = kDefaultKeepFinished)
      : keep_finished_(keep_finished) {}

  // A new task "task-<n>", n counting up over every task so far (restored ones included).
  // Before it is made, the finished tasks that ended longest ago beyond `keep_finished` are
  // forgotten, so no reference to another record may be held across this call.
  TaskRecord& Create();
  // A journaled task under its own id; new ids continue after `next_number`.
  TaskRecord& Restore(const std::string& task_id, uint64_t next_number);
  TaskRecord* Find(const std::string& task_id);
  const TaskRecord* Find(const std::string& task_id) const;
  // Tasks of `robot_id` ("" = every robot), in submission order.
  std::vector<const TaskRecord*> Select(const std::string& robot_id, bool unfinished_only) const;
  // The number the next new task gets (journaled, so a restarted gateway never reuses an id).
  uint64_t next_number() const { return next_number_; }

  // Every task, by id. Records never move; only Create() forgets finished ones.
  std::map<std::string, TaskRecord>& all() { return tasks_; }
  const std::map<std::string, TaskRecord>& all() const { return tasks_; }

 private:
  // Forgets the finished tasks that ended longest ago (last update; submission order among
  // equals) beyond `keep_finished_`; a task inside a remote call or waiting for a vision answer
  // stays.
  void ForgetOldFinished();

  std::size_t keep_finished_;
  std::map<std::string, TaskRecord> tasks_;
  uint64_t next_number_ = 1;
};

}  // namespace semnav::reasoning
