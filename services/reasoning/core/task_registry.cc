#include "services/reasoning/core/task_registry.h"

#include <algorithm>
#include <tuple>

#include "absl/strings/str_cat.h"

namespace semnav::reasoning {

namespace {

bool SameTarget(const std::optional<LocatedTarget>& a, const std::optional<LocatedTarget>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a.has_value()) return true;
  return a->object_id == b->object_id && a->position == b->position &&
         a->confidence == b->confidence && a->path == b->path;
}

bool SameArea(const std::optional<SearchArea>& a, const std::optional<SearchArea>& b) {
  if (a.has_value() != b.has_value()) return false;
  return !a.has_value() || (a->min == b->min && a->max == b->max);
}

}  // namespace

bool SameContent(const TaskView& a, const TaskView& b) {
  return std::tie(a.task_id, a.robot_id, a.instruction, a.state, a.pending, a.subgoals,
                  a.current_subgoal, a.phase, a.reason, a.path, a.progress, a.decomposition_source,
                  a.replans, a.explore_goals, a.model_requests, a.model_calls,
                  a.exploration_strategy, a.created) ==
             std::tie(b.task_id, b.robot_id, b.instruction, b.state, b.pending, b.subgoals,
                      b.current_subgoal, b.phase, b.reason, b.path, b.progress,
                      b.decomposition_source, b.replans, b.explore_goals, b.model_requests,
                      b.model_calls, b.exploration_strategy, b.created) &&
         SameTarget(a.target, b.target) && SameArea(a.search_area, b.search_area);
}

TaskView ViewOf(const TaskRecord& task, std::optional<ExplorationStrategy> exploration_strategy) {
  const TaskProgress& progress = task.executor->progress();
  TaskView view;
  view.task_id = task.task_id;
  view.robot_id = task.robot_id;
  view.instruction = task.instruction;
  view.state = progress.state;
  view.pending = !task.started && progress.state == TaskState::kRunning;
  view.revision = task.revision;
  view.subgoals = task.executor->subgoals();
  view.current_subgoal = progress.subgoal_index;
  view.phase = progress.phase;
  view.reason = progress.reason;
  view.target = progress.target;
  view.path = progress.path;
  const std::size_t count = view.subgoals.size();
  view.progress =
      count == 0 ? 1.0 : std::min(1.0, static_cast<double>(progress.subgoal_index) / count);
  view.decomposition_source = task.source;
  view.replans = progress.replans;
  view.explore_goals = progress.explore_goals;
  view.model_requests = progress.model_requests;
  view.model_calls = task.model_calls;
  view.exploration_strategy = exploration_strategy;
  view.search_area = task.search_area;
  view.created = task.created;
  view.updated = task.updated;
  return view;
}

TaskRecord& TaskRegistry::Create() {
  ForgetOldFinished();
  const std::string task_id = absl::StrCat("task-", next_number_++);
  TaskRecord& task = tasks_[task_id];
  task.task_id = task_id;
  return task;
}

TaskRecord& TaskRegistry::Restore(const std::string& task_id, uint64_t next_number) {
  next_number_ = std::max(next_number_, next_number);
  TaskRecord& task = tasks_[task_id];
  task.task_id = task_id;
  return task;
}

TaskRecord* TaskRegistry::Find(const std::string& task_id) {
  auto it = tasks_.find(task_id);
  return it == tasks_.end() ? nullptr : &it->second;
}

const TaskRecord* TaskRegistry::Find(const std::string& task_id) const {
  auto it = tasks_.find(task_id);
  return it == tasks_.end() ? nullptr : &it->second;
}

std::vector<const TaskRecord*> TaskRegistry::Select(const std::string& robot_id,
                                                    bool unfinished_only) const {
  std::vector<const TaskRecord*> selected;
  for (const auto& [id, task] : tasks_) {
    if (!robot_id.empty() && task.robot_id != robot_id) continue;
    if (unfinished_only && task.executor->finished()) continue;
    selected.push_back(&task);
  }
  // Ids are "task-<n>" with n counting up, so (length, id) is submission order.
  std::sort(selected.begin(), selected.end(), [](const TaskRecord* a, const TaskRecord* b) {
    return std::make_pair(a->task_id.size(), a->task_id) <
           std::make_pair(b->task_id.size(), b->task_id);
  });
  return selected;
}

void TaskRegistry::ForgetOldFinished() {
  std::vector<const TaskRecord*> finished;
  for (const TaskRecord* task : Select("", false)) {
    if (task->executor != nullptr && task->executor->finished() && !task->in_remote_call &&
        !task->vision_busy) {
      finished.push_back(task);
    }
  }
  if (finished.size() <= keep_finished_) return;
  // The longest ended go first. By submission order, a task that ran long while hundreds of
  // others came and went was forgotten the moment it ended, before its operator saw the end
  // (50-robot fleet, 300 s: GetTask NOT_FOUND for two such tasks).
  std::stable_sort(finished.begin(), finished.end(), [](const TaskRecord* a, const TaskRecord* b) {
    return a->updated < b->updated;
  });
  const std::size_t forget = finished.size() - keep_finished_;
  for (std::size_t i = 0; i < forget; ++i) {
    const std::string task_id = finished[i]->task_id;  // a copy: the record goes with the erase
    tasks_.erase(task_id);
  }
}

}  // namespace semnav::reasoning
