// GatewayHub: the task journal. Tasks, leases and events are flushed to config.state_directory
// every journal_flush_interval_s (state built under mu_, written outside it); a restarted gateway
// restores them. A task that had not ended comes back PAUSED ("gateway_restarted") and resumes
// on its robot's next state, so nothing moves on a pose from before the crash. A clean shutdown
// cancels unfinished tasks, so a stack started afresh never drives an old task.
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"

namespace semnav::reasoning {

using namespace hub_internal;

namespace {

constexpr char kRestartedReason[] = "gateway_restarted: resumes with the robot's next state";

}  // namespace

JournaledTask GatewayHub::JournalEntry(const Task& task) const {
  JournaledTask out;
  out.task_id = task.task_id;
  out.robot_id = task.robot_id;
  out.instruction = task.instruction;
  out.source = task.source;
  out.strategy = task.strategy;
  out.search_area = task.search_area;
  out.subgoals = task.executor->subgoals();
  out.progress = task.executor->progress();
  out.progress.path.clear();
  out.progress.target.reset();
  out.model_calls = task.model_calls;
  out.created = task.created;
  out.updated = task.updated;
  return out;
}

void GatewayHub::RestoreTask(const JournaledTask& saved, uint64_t next_number) {
  Task& task = tasks_.Restore(saved.task_id, next_number);
  task.robot_id = saved.robot_id;
  task.instruction = saved.instruction;
  task.source = saved.source;
  task.search_area = saved.search_area;
  task.model_calls = saved.model_calls;
  task.created = saved.created;
  task.updated = saved.updated;
  task.strategy = saved.strategy;
  task.planner = PlannerFor(saved.task_id, saved.strategy);
  if (Ended(saved.progress.state)) {
    // History only: no embedding, no EROI search, no model.
    task.executor = std::make_unique<TaskExecutor>(
        task.instruction, saved.subgoals, &resolver_, task.planner.get(),
        RobotRecord(task.robot_id).memory.get(), config_.executor);
    task.executor->Restore(saved.progress, saved.progress.reason);
    task.started = true;
    return;
  }
  InstallExecutor(task, saved.subgoals);
  // An operator's pause stays the operator's; any other unfinished task resumes by itself.
  const bool operator_paused = saved.progress.state == TaskState::kPaused &&
                               saved.progress.phase != "dependency_unavailable";
  task.executor->Restore(saved.progress,
                         operator_paused ? saved.progress.reason : kRestartedReason);
  task.started = true;
  task.resume_on_state = !operator_paused;
  RobotRecord(task.robot_id).active_task = task.task_id;  // a robot has one unfinished task at most
}

void GatewayHub::RestoreFromJournal() {
  absl::MutexLock journal_lock(&journal_mu_);
  absl::StatusOr<GatewayJournal> opened = GatewayJournal::Open(
      config_.state_directory, static_cast<std::size_t>(config_.retained_events));
  if (!opened.ok()) {
    LogError("gateway_journal_unavailable",
             {{"directory", config_.state_directory}, {"error", opened.status().ToString()}});
    return;
  }
  journal_ = std::make_unique<GatewayJournal>(*std::move(opened));
  absl::StatusOr<GatewayJournal::Recovered> recovered = journal_->Recover();
  if (!recovered.ok()) {
    // Kept for a person to look at; the gateway starts empty rather than not at all.
    const std::string aside = absl::StrCat(journal_->state_path(), ".damaged");
    std::error_code error;
    std::filesystem::rename(journal_->state_path(), aside, error);
    LogError("gateway_journal_damaged",
             {{"moved_to", aside}, {"error", recovered.status().ToString()}});
    return;
  }
  absl::MutexLock lock(&mu_);
  events_.Restore(recovered->events);
  leases_.Restore(recovered->state.leases, absl::Now());
  int resumable = 0;
  for (const JournaledTask& saved : recovered->state.tasks) {
    RestoreTask(saved, recovered->state.next_task);
    Task& task = *tasks_.Find(saved.task_id);
    Apply(task, {});  // publishes the restored snapshot (and logs PAUSED for unfinished tasks)
    if (!task.executor->finished()) {
      ++resumable;
      Log(api::EVENT_KIND_TASK_STATUS, task.robot_id, task.task_id,
          absl::StrCat(api::TaskStatus_Name(Snapshot(task).status()), ": ",
                       task.executor->progress().reason));
    }
  }
  if (!recovered->state.tasks.empty() || !recovered->events.empty()) {
    LogInfo("gateway_journal_restored", {{"tasks", recovered->state.tasks.size()},
                                         {"unfinished", resumable},
                                         {"events", recovered->events.size()},
                                         {"damaged_event_lines", recovered->damaged_event_lines}});
  }
  journal_dirty_ = true;
}

void GatewayHub::FlushJournal() {
  absl::MutexLock journal_lock(&journal_mu_);
  if (journal_ == nullptr) return;
  std::optional<GatewayState> state;
  std::vector<LoggedEvent> events;
  {
    absl::MutexLock lock(&mu_);
    events.swap(unjournaled_events_);
    if (journal_dirty_) {
      journal_dirty_ = false;
      state.emplace();
      state->next_task = tasks_.next_number();
      for (const auto& [id, task] : tasks_.all()) state->tasks.push_back(JournalEntry(task));
      state->leases = leases_.Unexpired(absl::Now());
    }
  }
  if (absl::Status s = journal_->AppendEvents(events); !s.ok()) {
    LogError("gateway_journal_write_failed",
             {{"file", journal_->events_path()}, {"error", s.ToString()}});
  }
  if (!state.has_value()) return;
  if (absl::Status s = journal_->SaveState(*state); !s.ok()) {
    LogError("gateway_journal_write_failed",
             {{"file", journal_->state_path()}, {"error", s.ToString()}});
    absl::MutexLock lock(&mu_);
    journal_dirty_ = true;  // try again next interval
  }
}

void GatewayHub::FlushJournalLoop() {
  const absl::Duration interval = absl::Seconds(config_.journal_flush_interval_s);
  while (true) {
    {
      absl::MutexLock lock(&mu_);
      mu_.AwaitWithTimeout(absl::Condition(&shut_down_), interval);
      if (shut_down_) return;  // Shutdown() writes the last flush itself
    }
    FlushJournal();
  }
}

}  // namespace semnav::reasoning
