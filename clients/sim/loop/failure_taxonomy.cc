#include "clients/sim/loop/failure_taxonomy.h"

#include <algorithm>
#include <string>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"

namespace semnav::sim::loop {
namespace {

namespace api = semnav::reasoning::v1;

// The gateway and the planners say why in words (TaskSnapshot.reason, feedback detail); these
// are the phrases of their failure messages ("no path to the exploration goal", "goal ... is
// outside the grid", "gave up after 3 re-plans: robot blocked", "target not found after ...").
bool Says(const std::string& text, absl::string_view phrase) {
  return absl::StrContains(absl::AsciiStrToLower(text), phrase);
}

int CountNoPath(const EpisodeTrace& trace) {
  int n = 0;
  for (const FeedbackEvent& f : trace.feedback) {
    if (f.kind == api::FEEDBACK_KIND_FAILED &&
        (Says(f.detail, "no path") || Says(f.detail, "unreachable") ||
         Says(f.detail, "not reachable")))
      ++n;
  }
  for (const TaskChange& t : trace.task) {
    if (Says(t.reason, "no path")) ++n;
  }
  return n;
}

int CountOutsideMap(const EpisodeTrace& trace) {
  int n = 0;
  for (const NavigateGoal& g : trace.goals) {
    if ((g.goal.array() < trace.bounds_min.array()).any() ||
        (g.goal.array() > trace.bounds_max.array()).any())
      ++n;
  }
  for (const FeedbackEvent& f : trace.feedback) {
    if (f.kind == api::FEEDBACK_KIND_FAILED && Says(f.detail, "outside")) ++n;
  }
  return n;
}

int CountBlocked(const EpisodeTrace& trace) {
  return static_cast<int>(
      std::count_if(trace.feedback.begin(), trace.feedback.end(),
                    [](const FeedbackEvent& f) { return f.kind == api::FEEDBACK_KIND_BLOCKED; }));
}

// A stretch of at least stuck_s during which the robot stayed within stuck_radius_m of where the
// stretch began.
bool Stuck(const EpisodeTrace& trace, const FailureTaxonomyConfig& config) {
  const std::vector<TraceSample>& s = trace.samples;
  for (size_t i = 0; i < s.size(); ++i) {
    size_t j = i;
    while (j + 1 < s.size() && (s[j + 1].position - s[i].position).norm() <= config.stuck_radius_m)
      ++j;
    if (s[j].time_s - s[i].time_s >= config.stuck_s) return true;
    if (j + 1 == s.size()) break;  // later stretches end at the same last sample, shorter
  }
  return false;
}

bool EverInRegion(const EpisodeTrace& trace) {
  return std::any_of(trace.samples.begin(), trace.samples.end(),
                     [](const TraceSample& s) { return s.in_success_region; });
}

std::optional<api::TaskStatus> FinalStatus(const EpisodeTrace& trace) {
  if (trace.task.empty()) return std::nullopt;
  return trace.task.back().status;
}

}  // namespace

std::string_view FailureCauseName(FailureCause cause) {
  switch (cause) {
    case FailureCause::kNone:
      return "";
    case FailureCause::kRefusedInstruction:
      return "refused_instruction";
    case FailureCause::kWrongObjectVerified:
      return "wrong_object_verified";
    case FailureCause::kStoppedOutsideRegion:
      return "stopped_outside_region";
    case FailureCause::kReachedNeverStopped:
      return "reached_never_stopped";
    case FailureCause::kGoalOutsideMap:
      return "goal_outside_map";
    case FailureCause::kCollisionLoop:
      return "collision_loop";
    case FailureCause::kNoPath:
      return "no_path";
    case FailureCause::kStuckInState:
      return "stuck_in_state";
    case FailureCause::kSeenNeverApproached:
      return "seen_never_approached";
    case FailureCause::kGaveUpSearching:
      return "gave_up_searching";
    case FailureCause::kTaskFailed:
      return "task_failed";
    case FailureCause::kBudgetSpentExploring:
      return "budget_spent_exploring";
  }
  return "";
}

FailureCause ClassifyFailure(const EpisodeTrace& trace, const FailureTaxonomyConfig& config) {
  if (trace.success) return FailureCause::kNone;
  if (trace.instruction_refused) return FailureCause::kRefusedInstruction;
  if (trace.stop_declared) {
    const double end_distance =
        trace.samples.empty() ? 0.0 : trace.samples.back().target_distance_m;
    return end_distance <= config.stopped_short_m ? FailureCause::kStoppedOutsideRegion
                                                  : FailureCause::kWrongObjectVerified;
  }
  if (trace.target_first_seen_s.has_value() && EverInRegion(trace))
    return FailureCause::kReachedNeverStopped;
  const std::optional<api::TaskStatus> status = FinalStatus(trace);
  const std::string final_reason = trace.task.empty() ? "" : trace.task.back().reason;
  const bool failed = status == api::TASK_STATUS_FAILED;
  if (CountOutsideMap(trace) >= config.outside_map_events ||
      (failed && Says(final_reason, "outside"))) {
    return FailureCause::kGoalOutsideMap;
  }
  if (CountBlocked(trace) >= config.collision_loop_blocks ||
      (failed && Says(final_reason, "blocked"))) {
    return FailureCause::kCollisionLoop;
  }
  if (CountNoPath(trace) >= config.no_path_events || (failed && Says(final_reason, "no path"))) {
    return FailureCause::kNoPath;
  }
  if (Stuck(trace, config)) return FailureCause::kStuckInState;
  if (trace.target_first_seen_s.has_value()) return FailureCause::kSeenNeverApproached;
  if (failed)
    return Says(final_reason, "not found") ? FailureCause::kGaveUpSearching
                                           : FailureCause::kTaskFailed;
  return FailureCause::kBudgetSpentExploring;
}

}  // namespace semnav::sim::loop
