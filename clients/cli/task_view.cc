#include "clients/cli/task_view.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "clients/cli/core/table.h"

namespace semnav::cli {

std::string StatusName(reasoning_api::TaskStatus status) {
  return ShortEnumName(reasoning_api::TaskStatus_Name(status), "TASK_STATUS_");
}

std::string SubgoalLabel(const reasoning_api::Subgoal& subgoal) {
  std::string label =
      ShortEnumName(reasoning_api::SubgoalType_Name(subgoal.type()), "SUBGOAL_TYPE_");
  const reasoning_api::TargetSpec& target = subgoal.target();
  std::vector<std::string> words(target.colours().begin(), target.colours().end());
  if (!target.name().empty()) words.push_back(target.name());
  if (!target.relation().empty() && !target.anchor().empty()) {
    words.push_back(absl::StrCat(target.relation(), " ", target.anchor()));
  }
  if (!words.empty()) absl::StrAppend(&label, " ", absl::StrJoin(words, " "));
  return label;
}

TaskProgress ToProgress(const reasoning_api::TaskSnapshot& task) {
  TaskProgress progress;
  progress.task_id = task.task_id();
  progress.status = StatusName(task.status());
  progress.progress = task.progress();
  progress.current_subgoal = task.current_subgoal();
  progress.subgoal_count = task.subgoals_size();
  if (task.current_subgoal() >= 0 && task.current_subgoal() < task.subgoals_size()) {
    progress.step = SubgoalLabel(task.subgoals(task.current_subgoal()));
  }
  progress.phase = task.phase();
  progress.reason = task.reason();
  return progress;
}

bool IsFinished(reasoning_api::TaskStatus status) {
  return status == reasoning_api::TASK_STATUS_SUCCEEDED ||
         status == reasoning_api::TASK_STATUS_FAILED ||
         status == reasoning_api::TASK_STATUS_CANCELLED;
}

ExitCode ExitCodeForTask(reasoning_api::TaskStatus status) {
  switch (status) {
    case reasoning_api::TASK_STATUS_SUCCEEDED:
      return ExitCode::kOk;
    case reasoning_api::TASK_STATUS_FAILED:
      return ExitCode::kTaskFailed;
    case reasoning_api::TASK_STATUS_CANCELLED:
      return ExitCode::kTaskCancelled;
    default:
      return ExitCode::kError;  // the watch ended before the task did
  }
}

std::string DescribeTask(const reasoning_api::TaskSnapshot& task) {
  std::string out = absl::StrCat(
      FormatProgressLine(ToProgress(task)), "\n", "robot:        ", task.robot_id(), "\n",
      "instruction:  ", task.instruction(), "\n", "revision:     ", task.revision(), "\n",
      "decomposed:   ", task.decomposition_source(), "\n", "replans:      ", task.replans(),
      ", explore goals ", task.explore_goals(), ", model requests ", task.model_requests(), "\n");
  if (task.has_target()) {
    const reasoning_api::ResolvedTarget& target = task.target();
    absl::StrAppend(
        &out, "target:       object ", target.object_id(), " '", target.label(), "' at (",
        FormatFixed(target.position().x(), 2), ", ", FormatFixed(target.position().y(), 2), ", ",
        FormatFixed(target.position().z(), 2), ") confidence ", FormatFixed(target.confidence(), 2),
        " ", ShortEnumName(reasoning_api::ResolutionPath_Name(target.path()), "RESOLUTION_PATH_"),
        "\n");
  }
  Table subgoals({"#", "STEP", "STATE", "REASON"});
  for (int i = 0; i < task.subgoals_size(); ++i) {
    const char* state = i < task.current_subgoal()    ? "done"
                        : i == task.current_subgoal() ? "active"
                                                      : "";
    subgoals.AddRow(
        {std::to_string(i + 1), SubgoalLabel(task.subgoals(i)), state, task.subgoals(i).reason()});
  }
  if (!subgoals.empty()) absl::StrAppend(&out, "\n", subgoals.Render());
  return out;
}

}  // namespace semnav::cli
