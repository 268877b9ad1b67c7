#include "services/reasoning/core/task_executor.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "services/common/geometry/segment.h"
#include "services/reasoning/core/input_limits.h"

namespace semnav::reasoning {
namespace {

// The detection count the glance doubts: a candidate seen exactly once.
constexpr int kSeenOnce = 1;

// The trail (the way the robot came): a point each time it has moved kTrailSpacingM, the newest
// kTrailPoints kept. Poses arrive every 0.5 m at most, so a longer step between two points is a
// jump of the pose (a relocalization's correction), not space the robot drove through.
constexpr double kTrailSpacingM = 0.25;
constexpr std::size_t kTrailPoints = 40;
constexpr double kTrailMaxStepM = 1.0;

}  // namespace

std::string_view TaskStateName(TaskState state) {
  switch (state) {
    case TaskState::kRunning:
      return "RUNNING";
    case TaskState::kPaused:
      return "PAUSED";
    case TaskState::kSucceeded:
      return "SUCCEEDED";
    case TaskState::kFailed:
      return "FAILED";
    case TaskState::kCancelled:
      return "CANCELLED";
  }
  return "UNKNOWN";
}

TaskExecutor::TaskExecutor(std::string instruction, std::vector<Subgoal> subgoals,
                           const FastResolver* resolver, PathPlanner* planner,
                           const TopologicalMemory* memory, ExecutorConfig config)
    : instruction_(std::move(instruction)),
      subgoals_(std::move(subgoals)),
      resolver_(resolver),
      planner_(planner),
      memory_(memory),
      config_(config) {}

bool TaskExecutor::finished() const { return Ended(progress_.state); }

const TargetSpec& TaskExecutor::ActiveTarget() const {
  const auto is_object = [](const Subgoal& goal) {
    return !goal.target.empty() && !goal.target.is_room;
  };
  if (is_object(current())) return current().target;
  for (int i = progress_.subgoal_index; i >= 0; --i) {
    if (is_object(subgoals_[static_cast<std::size_t>(i)]))
      return subgoals_[static_cast<std::size_t>(i)].target;
  }
  for (const Subgoal& goal : subgoals_) {
    if (is_object(goal)) return goal.target;
  }
  return current().target;
}

double TaskExecutor::YawTo(const Eigen::Vector3d& point) const {
  const Eigen::Vector3d d = point - pose_.position;
  return d.head<2>().norm() < 1e-9 ? pose_.yaw : std::atan2(d.y(), d.x());
}

std::vector<RobotCommand> TaskExecutor::Start(double now, const RobotPose& pose) {
  if (CheckRobotPose(pose, "pose").ok()) pose_ = pose;  // a bad pose never becomes a goal
  start_time_ = progress_since_ = now;
  progress_anchor_ = pose_.position;
  trail_.push_back(pose_.position);
  return EnterSubgoal(now);
}

std::vector<RobotCommand> TaskExecutor::MoveTo(double now, const Eigen::Vector3d& goal, double yaw,
                                               double speed, Phase phase, const std::string& reason,
                                               const std::optional<Eigen::Vector3d>& reach_target) {
  absl::StatusOr<std::vector<Eigen::Vector3d>> path = PlanPath(goal, reach_target);
  if (absl::IsUnavailable(path.status())) return PauseForDependency(now, path.status());
  if (!path.ok() && phase == Phase::kExploring) {
    // Without a frontier goal this was the fallback step: ExplorationFailed looks around rather
    // than chain more planning calls under the hub lock; the scan's end asks for a goal again.
    return ExplorationFailed(
        now, absl::StrCat("no path to the exploration goal: ", path.status().message()));
  }
  if (absl::IsNotFound(path.status())) {
    // No path to a known place: explore (the map grows) and try again when the target is seen.
    if (++progress_.replans > config_.max_replans) {
      return SetTargetAside(now, absl::StrCat("no path after ", config_.max_replans, " re-plans"));
    }
    progress_.reason = absl::StrCat("no path: ", path.status().message(), "; exploring");
    // Still on its way to an exploration goal: the robot drives on. Sending the same goal again
    // spent another goal of the budget at each map update (house_expo_room_0000 with the model:
    // 14 of its 30).
    if (phase_ == Phase::kExploring && explore_goal_.has_value()) return {};
    return Explore(now);
  }
  if (!path.ok()) return Replan(now, absl::StrCat("no path: ", path.status().message()));
  return Navigate(now, goal, *std::move(path), yaw, speed, phase, reason);
}

std::vector<RobotCommand> TaskExecutor::Navigate(double now, const Eigen::Vector3d& goal,
                                                 std::vector<Eigen::Vector3d> path, double yaw,
                                                 double speed, Phase phase,
                                                 const std::string& reason) {
  glancing_ = false;  // a new motion ends any glance (GoForCandidate starts one after this)
  RobotCommand command = NewCommand(CommandKind::kNavigate, reason);
  command.goal = goal;
  if (!path.empty())
    command.goal.head<2>() = path.back().head<2>();  // alternative point or adjusted goal
  command.goal_yaw = yaw;
  command.max_speed = speed;
  command.path = path;
  if (absl::Status refused = CheckCommand(command); !refused.ok()) return Refuse(refused);
  progress_.path = std::move(path);
  active_goal_ = command.goal;
  progress_.phase = phase == Phase::kExploring    ? "exploring"
                    : phase == Phase::kVerifying  ? "verifying"
                    : phase == Phase::kBackingOff ? "backing_off"
                                                  : "navigating";
  progress_.reason = reason;
  phase_ = phase;
  if (phase == Phase::kExploring) explore_chosen_at_ = now;
  phase_deadline_ =
      now + (phase == Phase::kVerifying ? config_.verify_timeout_s : config_.navigate_timeout_s);
  return {command};
}

double TaskExecutor::PathClearance() const {
  // After a block the path keeps more clearance (re-plan with inflated costs).
  return (config_.robot_radius_m > 0.0 ? config_.path_clearance_m : 0.0) + extra_clearance_m_;
}

absl::StatusOr<std::vector<Eigen::Vector3d>> TaskExecutor::PlanPath(
    const Eigen::Vector3d& goal, const std::optional<Eigen::Vector3d>& reach_target) {
  if ((goal - pose_.position).head<2>().norm() < 1e-6)
    return std::vector<Eigen::Vector3d>{};  // turn in place
  PathQuery query{pose_.position,  goal,        config_.multi_modal, config_.robot_radius_m,
                  PathClearance(), std::nullopt};
  query.contacts = contacts_;
  absl::StatusOr<std::vector<Eigen::Vector3d>> path = planner_->Plan(query);
  if (reach_target.has_value() &&
      (absl::IsFailedPrecondition(path.status()) || absl::IsNotFound(path.status()))) {
    // The stand-off point lies in furniture or is walled in (a laptop on a desk with its chair in
    // front, a cup on a counter seen from its end): stand at the free point nearest the target
    // that is still within reach, whichever side it is on. The line of sight from here, tried
    // next, can stop short of reach (hand-drawn flat, generated house).
    PathQuery near = query;
    near.goal = *reach_target;
    near.goal_tolerance_m = ReachRadius();
    absl::StatusOr<std::vector<Eigen::Vector3d>> reach = planner_->Plan(near);
    if (absl::IsUnavailable(reach.status())) return reach;
    // A point reached only by a long detour lies beyond a wall from here (the object's near
    // side fully blocked, the next room reachable through a door): the camera would not see the
    // object from there, so the line-of-sight point below is the better stand.
    if (reach.ok() && !reach->empty()) {
      const double straight = (reach->back() - pose_.position).head<2>().norm();
      const double way = HorizontalLength(pose_.position, *reach);
      if (way <= config_.reach_max_detour_factor * straight + config_.reach_detour_slack_m) {
        return reach;
      }
    }
  }
  if (absl::IsFailedPrecondition(path.status())) {
    // Seed 004: the goal lies in an obstacle; go to the free point nearest it seen from here.
    // Frontier goals too: they sit on the edge of the unknown, often in inflated cells.
    query.alternative_from = pose_.position;
    path = planner_->Plan(query);
  }
  return path;
}

std::vector<RobotCommand> TaskExecutor::Rotate(double now, double rate, double duration,
                                               Phase phase, const std::string& reason,
                                               double camera_tilt_rad) {
  RobotCommand command = NewCommand(CommandKind::kRotate, reason);
  command.angular_speed = rate;
  command.duration_s = duration;
  command.camera_tilt_rad = camera_tilt_rad;
  if (absl::Status refused = CheckCommand(command); !refused.ok()) return Refuse(refused);
  progress_.phase = "looking_around";
  progress_.reason = reason;
  phase_ = phase;
  phase_deadline_ = now + duration;
  return {command};
}

double TaskExecutor::LookUpTilt() const {
  const std::vector<std::string>& labels = config_.look_up_labels;
  if (std::find(labels.begin(), labels.end(), ActiveTarget().name) == labels.end()) return 0.0;
  return std::clamp(std::min(config_.look_up_tilt_rad, config_.camera_tilt_max_rad), 0.0,
                    kMaxCameraTiltRad);
}

bool TaskExecutor::LooksUpHere() const {
  if (LookUpTilt() <= 0.0 || config_.look_around_rate_rps <= 0.0) return false;
  return !looked_up_at_.has_value() ||
         (pose_.position - *looked_up_at_).head<2>().norm() >= config_.look_up_every_m;
}

std::vector<RobotCommand> TaskExecutor::Hold(double now, double duration,
                                             const std::string& reason) {
  RobotCommand command = NewCommand(CommandKind::kHold, reason);
  command.duration_s = duration;
  if (absl::Status refused = CheckCommand(command); !refused.ok()) return Refuse(refused);
  progress_.phase = "waiting";
  progress_.reason = reason;
  phase_ = Phase::kWaiting;
  phase_deadline_ = now + duration;
  return {command};
}

RobotCommand TaskExecutor::NewCommand(CommandKind kind, const std::string& reason) {
  RobotCommand command;
  command.kind = active_kind_ = kind;
  command.id = active_command_ = next_command_id_++;
  command.reason = reason;
  return command;
}

std::vector<RobotCommand> TaskExecutor::Halt(TaskState state, CommandKind kind,
                                             const std::string& reason) {
  progress_.state = state;
  progress_.reason = reason;
  phase_ = Phase::kIdle;
  if (Ended(state)) ReleaseSearchState();
  return {NewCommand(kind, reason)};
}

void TaskExecutor::ReleaseSearchState() {
  // The gateway keeps every task it ran for GetTask; an ended one needs only its progress. Its
  // copy of the scene graph (embeddings included) and search lists grew the gateway's memory by
  // each finished task (fleet bench, 50 robots: +11 MiB in 150 s).
  graph_ = EmptySceneGraph();
  text_embedding_ = {};
  spent_explore_goals_ = {};
  trail_ = {};
  blocked_spots_ = {};
  looked_around_at_blocks_ = {};
  failed_fallback_steps_ = {};
  pending_request_.reset();
}

std::vector<RobotCommand> TaskExecutor::Abandon(const std::string& reason) {
  if (Ended(progress_.state)) return {};
  dependency_wait_.reset();
  return Fail(reason);
}

std::vector<RobotCommand> TaskExecutor::Fail(const std::string& reason) {
  return Halt(TaskState::kFailed, CommandKind::kStop, reason);
}

std::vector<RobotCommand> TaskExecutor::PauseForDependency(double now,
                                                           const absl::Status& unavailable) {
  const std::string dependency = UnavailableDependency(unavailable);
  if (dependency_wait_.has_value()) {
    // A retry failed: the robot already holds; the timeout counts from the first failure.
    dependency_wait_->dependency = dependency;
    dependency_wait_->next_retry = now + config_.dependency_retry_s;
    progress_.state = TaskState::kPaused;
    progress_.phase = "dependency_unavailable";
    progress_.reason =
        absl::StrCat("dependency_unavailable: ", dependency, " (", unavailable.message(), ")");
    phase_ = Phase::kIdle;
    return {};
  }
  dependency_wait_ = DependencyWait{dependency, now, now + config_.dependency_retry_s};
  progress_.phase = "dependency_unavailable";
  progress_.path.clear();
  return Halt(
      TaskState::kPaused, CommandKind::kHold,
      absl::StrCat("dependency_unavailable: ", dependency, " (", unavailable.message(), ")"));
}

std::vector<RobotCommand> TaskExecutor::RetryDependency(double now) {
  const DependencyWait wait = *dependency_wait_;
  if (now - wait.since >= config_.dependency_timeout_s) {
    dependency_wait_.reset();
    return Fail(
        absl::StrCat(wait.dependency, " unavailable for ", config_.dependency_timeout_s, " s"));
  }
  // Re-enter the interrupted subgoal: it asks the planner again.
  progress_.state = TaskState::kRunning;
  std::vector<RobotCommand> out = EnterSubgoal(now);
  if (progress_.state == TaskState::kPaused && dependency_wait_.has_value()) return out;
  dependency_wait_.reset();
  progress_.reason = absl::StrCat("dependency_restored: ", wait.dependency, "; ", progress_.reason);
  return out;
}

std::vector<RobotCommand> TaskExecutor::Refuse(const absl::Status& refused) {
  // Whatever produced it (a planner's path, a model's duration, a bad pose), a non-finite or
  // absurd number must not reach the robot: the task ends and the robot stops.
  return Fail(absl::StrCat("refused to send the robot a command: ", refused.message()));
}

std::vector<RobotCommand> TaskExecutor::Replan(double now, const std::string& reason) {
  if (phase_ == Phase::kBackingOff) return ResumeAfterBackoff(now);
  if (exploring()) return ExplorationFailed(now, reason);
  return CountedReplan(now, reason);
}

std::vector<RobotCommand> TaskExecutor::CountedReplan(double now, const std::string& reason) {
  if (++progress_.replans > config_.max_replans) {
    if (progress_.target.has_value()) {
      return SetTargetAside(now, absl::StrCat("could not reach it after ", config_.max_replans,
                                              " re-plans: ", reason));
    }
    return Fail(absl::StrCat("gave up after ", config_.max_replans, " re-plans: ", reason));
  }
  progress_.reason = reason;
  return EnterSubgoal(now);
}

// Exploration is not the task: a goal that cannot be reached is blacklisted and the search goes
// on (explore_lite's frontier blacklist); the exploration budget bounds the search.
std::vector<RobotCommand> TaskExecutor::ExplorationFailed(double now, const std::string& reason) {
  if (!explore_goal_.has_value()) {
    // The fallback step failed: the same step would be chosen again, so look around first.
    return Rotate(now, config_.look_around_rate_rps, config_.look_around_duration_s,
                  Phase::kExploreScan, absl::StrCat(reason, "; looking around"));
  }
  SpendExploreGoal(*explore_goal_, /*unreachable=*/true);
  // A goal never reached explored nothing: it does not use the budget (the spent list bounds
  // the retries, since planning never offers it again).
  --progress_.explore_goals;
  explore_goal_.reset();
  std::vector<RobotCommand> out = Explore(now);
  if (progress_.state == TaskState::kRunning)
    progress_.reason = absl::StrCat(progress_.reason, " (", reason, ")");
  return out;
}

// A located target the robot cannot reach (blocked approach, no path) is set aside while the
// search goes on elsewhere; it is tried again from the next exploration goal, often from another
// side.
std::vector<RobotCommand> TaskExecutor::SetTargetAside(double now, const std::string& reason) {
  if (progress_.target.has_value()) set_aside_.insert(progress_.target->object_id);
  return ReleaseTarget(now, absl::StrCat("set aside: ", reason));
}

std::vector<RobotCommand> TaskExecutor::ReleaseTarget(double now, const std::string& reason) {
  const int64_t id = progress_.target.has_value() ? progress_.target->object_id : -1;
  progress_.target.reset();
  progress_.replans = 0;
  for (int i = 0; i < static_cast<int>(subgoals_.size()); ++i) {
    const Subgoal& goal = subgoals_[static_cast<std::size_t>(i)];
    if (goal.type == SubgoalType::kFind ||
        (goal.type == SubgoalType::kNavigate && !goal.target.is_room)) {
      progress_.subgoal_index = std::min(progress_.subgoal_index, i);
      break;
    }
  }
  std::vector<RobotCommand> out = Explore(now);
  if (progress_.state == TaskState::kRunning) {
    progress_.reason = absl::StrCat(progress_.reason, " (object ", id, " ", reason, ")");
  }
  return out;
}

std::vector<RobotCommand> TaskExecutor::NextSubgoal(double now, const std::string& reason) {
  progress_.reason = reason;
  progress_.replans = 0;
  ++progress_.subgoal_index;
  return EnterSubgoal(now);
}

bool TaskExecutor::TryResolve() {
  if (progress_.target.has_value() && excluded_.count(progress_.target->object_id) == 0)
    return true;
  progress_.target.reset();
  const std::set<int64_t> skip = SkippedObjects();
  const FastResolution resolution =
      resolver_->Resolve(ActiveTarget(), *graph_, text_embedding_, skip);
  if (!resolution.accepted) return false;
  const SceneObject* object = graph_->FindObject(resolution.best->object_id);
  progress_.target =
      LocatedTarget{object->id, object->position, resolution.best->fused, ResolutionPath::kFast, 0};
  return true;
}

void TaskExecutor::MaybeRequestModel() {
  if (!config_.model_available || awaiting_model_ || graph_->objects.empty() ||
      (progress_.model_requests > 0 && graph_->revision == requested_revision_)) {
    return;
  }
  GroundingConfig grounding;
  grounding.max_objects = config_.grounding_max_objects;
  // The model reads labels: an object whose appearance contradicts its label is not offered.
  const auto contradicted = [this](const SceneObject& object) {
    return AppearanceContradicts(object);
  };
  const SceneGraph* source = graph_.get();
  SceneGraph without_contradicted;
  if (std::any_of(graph_->objects.begin(), graph_->objects.end(), contradicted)) {
    without_contradicted = *graph_;
    std::erase_if(without_contradicted.objects, contradicted);
    source = &without_contradicted;
  }
  GroundedGraph grounded =
      SelectiveGrounding(ActiveTarget(), *source, resolver_->matcher(), grounding);
  // No candidate could be named: the proxy refuses an empty list, and asking again on every new
  // revision made a call (and a warning) every 200 ms while the robot explored.
  if (grounded.open_vocabulary) {
    // Classes, not instances: another instance of a class stands in for one set aside.
    // Classes the model already said are not the target are not shown again.
    SceneGraph offered = *graph_;
    const std::set<int64_t> skip = SkippedObjects();
    std::erase_if(offered.objects, [&](const SceneObject& object) {
      return skip.count(object.id) > 0 ||
             open_vocabulary_rejected_.count(
                 resolver_->matcher().Normalise(object.label, {}).name) > 0;
    });
    grounded = SelectiveGrounding(ActiveTarget(), offered, resolver_->matcher(), grounding);
  }
  if (grounded.graph.objects.empty()) return;
  if (grounded.open_vocabulary) {
    // Every revision moves some object; the question (which of these classes is the target?)
    // changes only with a new class or an object set aside. Measured: 61 calls, the task budget,
    // in one office episode before this.
    std::set<std::string> classes;
    for (const SceneObject& object : grounded.graph.objects) {
      classes.insert(resolver_->matcher().Normalise(object.label, {}).name);
    }
    std::string asked = absl::StrCat(SkippedObjects().size(), "|", absl::StrJoin(classes, ","));
    if (asked == open_vocabulary_asked_) return;
    open_vocabulary_asked_ = std::move(asked);
    open_vocabulary_pending_ = std::move(classes);
  } else {
    open_vocabulary_pending_.clear();
  }
  offered_labels_.clear();
  for (const SceneObject& object : grounded.graph.objects)
    offered_labels_[object.id] = object.label;
  ModelRequest request;
  request.graph_revision = requested_revision_ = graph_->revision;
  request.request = BuildResolveRequest(instruction_, ActiveTarget(), grounded.graph);
  request.grounded = std::move(grounded.graph);
  pending_request_ = std::move(request);
  awaiting_model_ = true;
  ++progress_.model_requests;
}

std::optional<ModelRequest> TaskExecutor::TakeModelRequest() {
  std::optional<ModelRequest> request = std::move(pending_request_);
  pending_request_.reset();
  return request;
}

std::vector<RobotCommand> TaskExecutor::Explore(double now) {
  if (InEndgame(now) && current().type != SubgoalType::kExplore && TakeBestCandidate())
    return GoToBestCandidate(now);
  if (current().type != SubgoalType::kExplore && TakeLabelledCandidate())
    return GoForCandidate(now);
  // What ends a search: a task with a time budget searches until it is spent (the step budget of
  // Habitat's ObjectNav, VLFM and ApexNav); one without stops after max_explore_goals. A goal
  // count alone charges a strategy by the shortness of its legs: seed 000's search flies short
  // hops between the regions the model names, and stopped on the 30th with a fifth of the budget
  // left. An exploration step of a plan keeps the count: the steps after it need the time.
  const bool budget_ends_search =
      config_.time_budget_s > 0.0 && current().type != SubgoalType::kExplore;
  if (budget_ends_search && now - start_time_ >= config_.time_budget_s) {
    return Fail(absl::StrCat("target not found in the time budget (", progress_.explore_goals,
                             " exploration goals)"));
  }
  if (!budget_ends_search && progress_.explore_goals >= config_.max_explore_goals) {
    if (current().type == SubgoalType::kExplore) return NextSubgoal(now, "exploration budget used");
    return Fail(
        absl::StrCat("target not found after ", progress_.explore_goals, " exploration goals"));
  }
  ++progress_.explore_goals;
  // Frontiers behind furniture or in unseen corners can be approached no closer than where the
  // robot stands (the alternative point is here): spend them and ask planning for the next.
  constexpr int kGoalsPerStep = 3;  // each is a planning call the task waits for: keep them few
  for (int attempt = 0; attempt < kGoalsPerStep; ++attempt) {
    const absl::StatusOr<Eigen::Vector3d> goal =
        planner_->ExplorationGoal(ExplorationRequest(std::nullopt));
    if (absl::IsUnavailable(goal.status())) return PauseExploring(now, goal.status());
    if (!goal.ok()) break;
    explore_goal_ = *goal;
    absl::StatusOr<std::vector<Eigen::Vector3d>> path = PlanPath(*goal);
    if (absl::IsUnavailable(path.status())) return PauseExploring(now, path.status());
    if (LeadsAway(path, *goal))
      return Navigate(now, *goal, *std::move(path), YawTo(*goal), 0.0, Phase::kExploring,
                      "exploring for the target");
    // No path: the frontiers around it lie in the same unreachable pocket.
    SpendExploreGoal(*goal, absl::IsNotFound(path.status()));
  }
  return FallbackStep(now);
}

ExplorationQuery TaskExecutor::ExplorationRequest(
    const std::optional<Eigen::Vector3d>& keep_goal) const {
  ExplorationQuery query{pose_,
                         spent_explore_goals_,
                         config_.explore_exclusion_radius_m,
                         config_.platform,
                         keep_goal,
                         keep_goal.has_value() ? config_.explore_keep_radius_m : 0.0};
  // A rolling robot's goal is a cell its footprint stands on, so the path to it is planned at
  // the first try; a multi-modal one flies over what blocks the footprint.
  if (config_.explore_with_footprint && !config_.multi_modal) {
    query.robot_radius_m = config_.robot_radius_m;
    query.clearance_m = PathClearance();
  }
  return query;
}

bool TaskExecutor::LeadsAway(const absl::StatusOr<std::vector<Eigen::Vector3d>>& path,
                             const Eigen::Vector3d& goal) const {
  // An empty path lets the robot plan locally, unless the goal is where it stands (PlanPath's
  // "turn in place"): EROI_UTILITY sent the UAV's own spot 30 times in 7 s.
  if (!path.ok()) return false;
  const Eigen::Vector3d end = path->empty() ? goal : path->back();
  return (end - pose_.position).head<2>().norm() >= config_.min_explore_step_m;
}

std::vector<RobotCommand> TaskExecutor::ReselectExploreGoal(double now) {
  explore_chosen_at_ = now;
  const absl::StatusOr<Eigen::Vector3d> goal =
      planner_->ExplorationGoal(ExplorationRequest(explore_goal_));
  if (absl::IsUnavailable(goal.status())) return PauseExploring(now, goal.status());
  // No frontier left, the same one, or one turned away from before: the robot drives on (its
  // goal is spent on arrival).
  const auto near_goal = [&](const Eigen::Vector3d& other) {
    return (*goal - other).head<2>().norm() <= config_.explore_keep_radius_m;
  };
  if (!goal.ok() || near_goal(*explore_goal_) ||
      std::any_of(explore_turned_from_.begin(), explore_turned_from_.end(), near_goal))
    return {};
  absl::StatusOr<std::vector<Eigen::Vector3d>> path = PlanPath(*goal);
  if (absl::IsUnavailable(path.status())) return PauseExploring(now, path.status());
  if (!LeadsAway(path, *goal))
    return {};  // asked again at the next period; arrival spends the old goal as before
  explore_turned_from_.push_back(*explore_goal_);
  explore_goal_ = *goal;  // the old goal is not spent: its frontier, if any is left, stays open
  return Navigate(now, *goal, *std::move(path), YawTo(*goal), 0.0, Phase::kExploring,
                  "exploring for the target (a better exploration goal)");
}

// No usable frontier from planning: step toward the least-explored sector of the topological
// memory, then its neighbours; directions that had no path are not asked again.
std::vector<RobotCommand> TaskExecutor::FallbackStep(double now) {
  constexpr int kDirections = 8;
  constexpr int kStepsPerCall = 3;  // each is a planning call the task waits for
  explore_goal_.reset();
  const double least = memory_ != nullptr ? memory_->LeastExploredYaw(pose_.position) : pose_.yaw;
  int asked = 0;
  for (int k = 0; k < kDirections && asked < kStepsPerCall; ++k) {
    const int side = (k + 1) / 2 * (k % 2 == 1 ? 1 : -1);  // 0, +1, -1, +2, -2, ... sectors
    const double yaw = least + side * (2.0 * M_PI / kDirections);
    const Eigen::Vector3d target =
        pose_.position +
        config_.fallback_explore_step_m * Eigen::Vector3d(std::cos(yaw), std::sin(yaw), 0.0);
    const bool failed_before =
        std::any_of(failed_fallback_steps_.begin(), failed_fallback_steps_.end(),
                    [&](const Eigen::Vector3d& failed) {
                      return (failed - target).head<2>().norm() <= config_.unreachable_region_m;
                    });
    if (failed_before) continue;
    ++asked;
    if (!StepKeepsToTheArea(target)) {  // as a step with no path
      failed_fallback_steps_.push_back(target);
      continue;
    }
    absl::StatusOr<std::vector<Eigen::Vector3d>> path = PlanPath(target);
    if (absl::IsUnavailable(path.status())) return PauseExploring(now, path.status());
    if (LeadsAway(path, target)) {
      return Navigate(now, target, *std::move(path), YawTo(target), 0.0, Phase::kExploring,
                      "exploring for the target");
    }
    // No path, or one that ends where the robot stands (the step lies in furniture next to it,
    // and the free point nearest it is here): a step that leads nowhere.
    if (path.ok() || absl::IsNotFound(path.status())) failed_fallback_steps_.push_back(target);
  }
  // Nothing can be planned from here: the robot may stand where planning cannot start (a narrow
  // gap, an inflated wall). Retrace the way it came once, then look around.
  if (!last_fallback_backed_off_) {
    std::vector<RobotCommand> retreat =
        RetraceTrail(now, "no path to the exploration goal from here; backing off");
    if (!retreat.empty()) {
      last_fallback_backed_off_ = true;
      --progress_.explore_goals;  // the exploration step after backing off asks again
      return retreat;
    }
  }
  last_fallback_backed_off_ = false;
  return Rotate(now, config_.look_around_rate_rps, config_.look_around_duration_s,
                Phase::kExploreScan, "no path to the exploration goal; looking around");
}

bool TaskExecutor::StepKeepsToTheArea(const Eigen::Vector3d& target) const {
  if (!config_.search_area.has_value()) return true;
  const SearchArea& area = *config_.search_area;
  const auto outside_by = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector2d q = p.head<2>();
    return (q - q.cwiseMax(area.min).cwiseMin(area.max)).norm();  // 0 inside
  };
  const double robot_out = outside_by(pose_.position);
  return robot_out == 0.0 || outside_by(target) < robot_out;
}

void TaskExecutor::SpendExploreGoal(const Eigen::Vector3d& goal, bool unreachable) {
  spent_explore_goals_.push_back(goal);
  // Planning excludes a disc of excluded_radius_m (0 = 1 m) around each spent goal: cover the
  // region with such discs on a hexagonal lattice (spacing sqrt(3) r covers the plane).
  const double r =
      config_.explore_exclusion_radius_m > 0.0 ? config_.explore_exclusion_radius_m : 1.0;
  const double region = config_.unreachable_region_m;
  if (!unreachable || region <= r) return;
  const double spacing = std::sqrt(3.0) * r;
  const int n = static_cast<int>(std::ceil(region / spacing)) + 1;
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      const Eigen::Vector3d offset(spacing * (i + 0.5 * j), spacing * (std::sqrt(3.0) / 2.0) * j,
                                   0.0);
      const double distance = offset.head<2>().norm();
      if (distance > 1e-9 && distance <= region) spent_explore_goals_.push_back(goal + offset);
    }
  }
}

bool TaskExecutor::InEndgame(double now) const {
  return config_.time_budget_s > 0.0 &&
         now - start_time_ >= config_.time_budget_s - config_.endgame_s;
}

std::optional<ScoredObject> TaskExecutor::BestCandidate() const {
  const std::set<int64_t> skip = SkippedObjects();
  const FastResolution resolution =
      resolver_->Resolve(ActiveTarget(), *graph_, text_embedding_, skip);
  if (!resolution.best.has_value() || graph_->FindObject(resolution.best->object_id) == nullptr)
    return std::nullopt;
  return resolution.best;
}

bool TaskExecutor::TakeBestCandidate() {
  if (endgame_taken_ || progress_.target.has_value()) return false;
  const std::optional<ScoredObject> best = BestCandidate();
  if (!best.has_value() || best->label < config_.endgame_min_label_match) return false;
  endgame_taken_ = true;
  // The fast path found it (below its threshold): reported as a fast-path resolution.
  progress_.target = LocatedTarget{best->object_id, graph_->FindObject(best->object_id)->position,
                                   best->fused, ResolutionPath::kFast, 0};
  return true;
}

bool TaskExecutor::RuledOut(int64_t id) const {
  const auto it = ruled_out_at_.find(id);
  if (it == ruled_out_at_.end()) return false;
  const SceneObject* object = graph_->FindObject(id);
  return object != nullptr &&
         (object->position - it->second).head<2>().norm() <= config_.success_radius_m;
}

std::set<int64_t> TaskExecutor::SkippedObjects() const {
  std::set<int64_t> skip = excluded_;
  skip.insert(set_aside_.begin(), set_aside_.end());
  for (const auto& [id, where] : ruled_out_at_) {
    if (RuledOut(id)) skip.insert(id);
  }
  for (const auto& [id, detections] : passed_by_) {
    const SceneObject* object = graph_->FindObject(id);
    if (object != nullptr && object->detection_count <= detections) skip.insert(id);
  }
  for (const SceneObject& object : graph_->objects) {
    if (AppearanceContradicts(object)) skip.insert(object.id);
  }
  return skip;
}

bool TaskExecutor::AppearanceContradicts(const SceneObject& object) const {
  if (config_.min_appearance_agreement <= 0.0 || text_embedding_.empty() ||
      object.embedding.empty()) {
    return false;
  }
  return Cosine(object.embedding, text_embedding_) < config_.min_appearance_agreement &&
         ReadsAsTarget(object);
}

bool TaskExecutor::ReadsAsTarget(const SceneObject& object) const {
  const LabelMatcher& matcher = resolver_->matcher();
  return matcher.Match(ActiveTarget(), matcher.Normalise(object.label, object.attributes)) > 0.0;
}

bool TaskExecutor::TakeLabelledCandidate() {
  if (config_.model_available || progress_.target.has_value()) return false;
  const std::optional<ScoredObject> best = BestCandidate();
  if (!best.has_value() || best->label < config_.approach_label_match) return false;
  progress_.target = LocatedTarget{best->object_id, graph_->FindObject(best->object_id)->position,
                                   best->fused, ResolutionPath::kFast, 0};
  return true;
}

std::vector<RobotCommand> TaskExecutor::GoForCandidate(double now) {
  const int64_t id = progress_.target->object_id;
  const SceneObject* object = graph_->FindObject(id);
  // Only a single detection is doubted: objects the map holds without detections (a loaded or
  // operator-placed map) and those seen twice are driven to at once.
  if (config_.glance_s <= 0.0 || object == nullptr || object->detection_count != kSeenOnce)
    return EnterSubgoal(now);
  std::vector<RobotCommand> out =
      MoveTo(now, pose_.position, YawTo(progress_.target->position), 0.0, Phase::kVerifying,
             absl::StrCat("object ", id, " seen once: looking at it again before driving to it"));
  if (phase_ == Phase::kVerifying) glancing_ = true;
  return out;
}

std::vector<RobotCommand> TaskExecutor::PassBy(double now) {
  glancing_ = false;
  const int64_t id = progress_.target->object_id;
  const SceneObject* object = graph_->FindObject(id);
  passed_by_[id] = object != nullptr ? object->detection_count : kSeenOnce;
  return ReleaseTarget(
      now, absl::StrCat("passed by: not detected again in a ", config_.glance_s, " s glance"));
}

std::vector<RobotCommand> TaskExecutor::GoToBestCandidate(double now) {
  const int64_t id = progress_.target->object_id;
  std::vector<RobotCommand> out = EnterSubgoal(now);
  if (progress_.state == TaskState::kRunning) {
    progress_.reason =
        absl::StrCat(progress_.reason, " (endgame: ", config_.time_budget_s - (now - start_time_),
                     " s left, best candidate seen: object ", id, ")");
  }
  return out;
}

std::vector<RobotCommand> TaskExecutor::PauseExploring(double now,
                                                       const absl::Status& unavailable) {
  --progress_.explore_goals;  // no goal was driven to: the retry asks again
  explore_goal_.reset();
  return PauseForDependency(now, unavailable);
}

std::vector<RobotCommand> TaskExecutor::Search(double now) {
  MaybeRequestModel();
  // Look around before choosing where to go: the target may stand behind the robot.
  if (!start_scan_done_ && config_.start_scan_duration_s > 0.0) {
    start_scan_done_ = true;
    return Rotate(now, config_.look_around_rate_rps, config_.start_scan_duration_s,
                  Phase::kExploreScan, "looking around before exploring");
  }
  return Explore(now);
}

std::vector<RobotCommand> TaskExecutor::EnterSubgoal(double now) {
  if (progress_.state != TaskState::kRunning) return {};
  if (progress_.subgoal_index >= static_cast<int>(subgoals_.size())) {
    progress_.phase = "done";
    return Halt(TaskState::kSucceeded, CommandKind::kStop, "task complete");
  }
  const Subgoal& goal = current();
  switch (goal.type) {
    case SubgoalType::kNavigate: {
      if (goal.target.is_room) {
        for (const SceneRegion& region : graph_->regions) {
          if (!resolver_->matcher().SameName(region.name, goal.target.name) ||
              region.object_ids.empty())
            continue;
          Eigen::Vector3d centre = Eigen::Vector3d::Zero();
          int count = 0;
          for (int64_t id : region.object_ids) {
            if (const SceneObject* object = graph_->FindObject(id)) {
              centre += object->position;
              ++count;
            }
          }
          if (count > 0) {
            centre /= count;
            return MoveTo(now, centre, YawTo(centre), 0.0, Phase::kMoving,
                          "going to " + goal.target.name);
          }
        }
        return NextSubgoal(now, goal.target.name + " is not in the map yet; searching from here");
      }
      if (!TryResolve()) return Search(now);
      const Eigen::Vector3d to_target = progress_.target->position - pose_.position;
      const double distance = to_target.head<2>().norm();
      if (distance <= config_.navigate_standoff_m)
        return NextSubgoal(now, "already near the target");
      const Eigen::Vector3d stop =
          progress_.target->position - to_target * (config_.navigate_standoff_m / distance);
      return MoveTo(now, stop, YawTo(progress_.target->position), 0.0, Phase::kMoving,
                    "going to the target");
    }
    case SubgoalType::kFind:
      if (TryResolve())
        return NextSubgoal(now, absl::StrCat("found object ", progress_.target->object_id));
      return Search(now);
    case SubgoalType::kLookAround:
      if (progress_.target.has_value()) return NextSubgoal(now, "target already located");
      return Rotate(now, config_.look_around_rate_rps, config_.look_around_duration_s,
                    Phase::kRotating, "looking around");
    case SubgoalType::kApproach: {
      if (!TryResolve()) return Search(now);
      const double stand_off = goal.distance_m > 0.0 ? goal.distance_m : 0.5;
      const Eigen::Vector3d to_target = progress_.target->position - pose_.position;
      const double distance = to_target.head<2>().norm();
      if (distance <= stand_off + 1e-6) return NextSubgoal(now, "already close");
      const Eigen::Vector3d stop = progress_.target->position - to_target * (stand_off / distance);
      return MoveTo(now, stop, YawTo(progress_.target->position), config_.approach_speed_mps,
                    Phase::kMoving, "approaching the target", progress_.target->position);
    }
    case SubgoalType::kVerify: {
      if (!TryResolve()) return Search(now);
      StartVerifyLook(graph_->FindObject(progress_.target->object_id));
      return MoveTo(now, pose_.position, YawTo(progress_.target->position), 0.0, Phase::kVerifying,
                    "turning to face the target to verify it");
    }
    case SubgoalType::kBacktrack: {
      std::optional<Eigen::Vector3d> back =
          memory_ != nullptr ? memory_->BacktrackPosition(goal.target) : std::nullopt;
      if (!back.has_value()) return NextSubgoal(now, "nothing to backtrack to");
      return MoveTo(now, *back, YawTo(*back), 0.0, Phase::kMoving, "backtracking");
    }
    case SubgoalType::kExplore:
      return Explore(now);
    case SubgoalType::kWait:
      return Hold(now, goal.duration_s > 0.0 ? goal.duration_s : config_.wait_duration_s,
                  "waiting");
  }
  return {};
}

std::vector<RobotCommand> TaskExecutor::HoldToVerify(double now) {
  // The window runs on the executor's clock (OnPose ends it at the deadline); a hold already
  // sent ends on the robot's timer, which may run a step ahead of it: keep waiting then.
  if (now >= phase_deadline_) return VerifyTimedOut(now);
  if (active_kind_ == CommandKind::kHold) return {};
  if (glancing_) phase_deadline_ = now + config_.glance_s;  // the glance counts from facing it
  // Facing the target: the robot is told at once to hold for the rest of the window, rather than
  // left without a command until detections (or the vision model) decide.
  RobotCommand command = NewCommand(
      CommandKind::kHold,
      absl::StrCat(glancing_ ? "glancing at object " : "verifying object ",
                   progress_.target->object_id, ": holding while detections confirm it"));
  command.duration_s = phase_deadline_ - now;
  command.camera_tilt_rad = LookUpTilt();  // a target that hangs high is framed tilted up
  if (absl::Status refused = CheckCommand(command); !refused.ok()) return Refuse(refused);
  progress_.reason = command.reason;
  return {command};
}

Eigen::Vector2d TaskExecutor::TargetHalfExtent() const {
  const SceneObject* object = graph_->FindObject(progress_.target->object_id);
  if (object == nullptr || !object->size.allFinite()) return Eigen::Vector2d::Zero();
  return (0.5 * object->size.head<2>()).cwiseMax(0.0).cwiseMin(config_.reach_extent_cap_m);
}

double TaskExecutor::ReachRadius() const {
  return std::max(0.0, config_.success_radius_m - config_.success_margin_m) +
         TargetHalfExtent().norm();
}

double TaskExecutor::DistanceToTarget(const Eigen::Vector3d& point) const {
  const Eigen::Vector2d offset = (point - progress_.target->position).head<2>().cwiseAbs();
  return (offset - TargetHalfExtent()).cwiseMax(0.0).norm();
}

std::vector<RobotCommand> TaskExecutor::CheckSuccessOrApproach(double now) {
  // Within reach less the margin, as success in view: the map's extent of the object is an
  // estimate (stopped 1.04 m from a toaster on a counter with the margin left out). An approach
  // that cannot get closer settles for the radius itself (a TV on a desk in a corner).
  const double distance = DistanceToTarget(pose_.position);
  if (distance <= config_.success_radius_m - config_.success_margin_m)
    return NextSubgoal(now, "target verified within the success radius");
  constexpr double kSameSpotM = 0.25;
  if (too_far_at_.has_value() && (*too_far_at_ - pose_.position).head<2>().norm() <= kSameSpotM) {
    too_far_at_.reset();
    if (distance <= config_.success_radius_m)
      return NextSubgoal(now, "target verified within the success radius; no closer approach");
    return SetTargetAside(now, "the approach cannot get within the success radius");
  }
  too_far_at_ = pose_.position;
  for (int i = progress_.subgoal_index; i >= 0; --i) {
    if (subgoals_[static_cast<std::size_t>(i)].type == SubgoalType::kApproach) {
      progress_.subgoal_index = i;
      return EnterSubgoal(now);
    }
  }
  const Eigen::Vector3d to_target = progress_.target->position - pose_.position;
  const Eigen::Vector3d stop =
      progress_.target->position - to_target * (0.5 / to_target.head<2>().norm());
  return MoveTo(now, stop, YawTo(progress_.target->position), config_.approach_speed_mps,
                Phase::kMoving, "verified but too far: approaching", progress_.target->position);
}

std::vector<RobotCommand> TaskExecutor::TargetReached(double now, const std::string& reason) {
  const std::string name = ActiveTarget().name;
  int next = progress_.subgoal_index;
  for (; next < static_cast<int>(subgoals_.size()); ++next) {
    const Subgoal& goal = subgoals_[static_cast<std::size_t>(next)];
    const bool about_target = goal.type == SubgoalType::kFind ||
                              goal.type == SubgoalType::kApproach ||
                              goal.type == SubgoalType::kVerify ||
                              (goal.type == SubgoalType::kNavigate && !goal.target.is_room);
    if (goal.type != SubgoalType::kLookAround && !(about_target && goal.target.name == name)) break;
  }
  progress_.subgoal_index = next - 1;  // NextSubgoal steps past the last one about the target
  return NextSubgoal(now, reason);
}

std::optional<std::vector<RobotCommand>> TaskExecutor::SuccessInView(double now,
                                                                     int fresh_detections) {
  if (!progress_.target.has_value() || phase_ == Phase::kIdle) return std::nullopt;
  const SubgoalType type = current().type;
  const bool about_target = type == SubgoalType::kApproach || type == SubgoalType::kVerify ||
                            (type == SubgoalType::kNavigate && !current().target.is_room);
  if (!about_target) return std::nullopt;
  if (close_target_ != progress_.target->object_id) {
    close_target_ = progress_.target->object_id;
    close_detections_ = 0;
  }
  const double distance = DistanceToTarget(pose_.position);
  if (distance > config_.success_radius_m - config_.success_margin_m) {
    close_detections_ = 0;
    return std::nullopt;
  }
  close_detections_ += fresh_detections;
  if (close_detections_ < config_.verify_detections) return std::nullopt;
  return TargetReached(now, absl::StrCat("object ", progress_.target->object_id, " in view within ",
                                         absl::SixDigits(distance), " m: stopping"));
}

void TaskExecutor::StartVerifyLook(const SceneObject* object) {
  progress_.target->detections_at_verify = object != nullptr ? object->detection_count : 0;
  progress_.target->misses_at_verify = object != nullptr ? object->miss_count : 0;
}

bool TaskExecutor::SeenMissing(const SceneObject& object) const {
  return config_.verify_rule_out_misses > 0 &&
         object.detection_count == progress_.target->detections_at_verify &&
         object.miss_count - progress_.target->misses_at_verify >= config_.verify_rule_out_misses;
}

std::vector<RobotCommand> TaskExecutor::VerifyTimedOut(double now, bool seen_missing) {
  if (glancing_) return PassBy(now);
  const int64_t id = progress_.target->object_id;
  const SceneObject* object = graph_->FindObject(id);
  const double distance = DistanceToTarget(pose_.position);
  // Accepted only when seen from within reach at least once: a misplaced or phantom object
  // (office_03: a "tv" mapped on the wrong side of a cabinet) never is. The acceptance is for a
  // camera that cannot frame the target close up; one that framed it and saw nothing does not.
  // A target that hangs high (look_up_labels) is above even the tilted camera's view within
  // reach: the detections that confirmed it from afar (the glance's verify_detections) stand.
  const bool hangs_high = LookUpTilt() > 0.0;
  const bool seen_within_reach = close_target_ == id && close_detections_ >= 1;
  const int needed = hangs_high ? config_.verify_detections : config_.verify_accept_detections;
  if (!seen_missing && object != nullptr &&
      distance <= config_.success_radius_m - config_.success_margin_m &&
      (seen_within_reach || hangs_high) && object->detection_count >= needed) {
    return TargetReached(now, absl::StrCat("object ", id, " accepted: ", object->detection_count,
                                           " detections, within reach, none new while facing it"));
  }
  if (second_look_target_ != id) {
    second_look_target_ = id;
    // One more look from verify_view_m: the robot's side first, then from other sides (the
    // approach may have ended at an alternative point behind furniture). A view point counts
    // only when its planned path ends within reach of the target.
    constexpr int kSides = 8;
    constexpr int kViewPlans = 3;  // each is a planning call the task waits for
    const Eigen::Vector3d target = progress_.target->position;
    Eigen::Vector3d away = pose_.position - target;
    away.z() = 0.0;
    const double own_side = away.norm() > 1e-6 ? std::atan2(away.y(), away.x()) : pose_.yaw + M_PI;
    StartVerifyLook(object);
    for (int k = 0, planned = 0; k < kSides && planned < kViewPlans; ++k) {
      const int side = (k + 1) / 2 * (k % 2 == 1 ? 1 : -1);  // 0, +45, -45, +90, ... deg
      const double angle = own_side + side * (2.0 * M_PI / kSides);
      Eigen::Vector3d view =
          target + config_.verify_view_m * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
      view.z() = pose_.position.z();
      ++planned;
      absl::StatusOr<std::vector<Eigen::Vector3d>> path = PlanPath(view);
      if (absl::IsUnavailable(path.status())) return PauseForDependency(now, path.status());
      if (!path.ok()) continue;
      const Eigen::Vector3d end = path->empty() ? view : path->back();
      if (DistanceToTarget(end) > config_.success_radius_m) continue;
      const Eigen::Vector3d to_target = target - end;
      return Navigate(
          now, view, *std::move(path), std::atan2(to_target.y(), to_target.x()), 0.0,
          Phase::kVerifying,
          absl::StrCat("object ", id, " not confirmed yet: looking again from ",
                       config_.verify_view_m, " m", side == 0 ? "" : " on another side"));
    }
  }
  second_look_target_ = -1;
  // Looked at twice from within reach and never detected there: the detections that made it a
  // candidate were false or another object's (home_04: one phantom "bowl" verified four times,
  // 100 s of the budget). Ruled out while the map keeps it there (a misplaced object that later
  // views move is tried at its new place); an object merely out of reach is set aside.
  const std::string missing = absl::StrCat("not detected in ", config_.verify_rule_out_misses,
                                           " views that should have shown it, on a second look");
  if (distance <= config_.success_radius_m) {
    ruled_out_at_[id] = progress_.target->position;
    return ReleaseTarget(now, seen_missing
                                  ? absl::StrCat("ruled out: ", missing)
                                  : absl::StrCat("ruled out: not confirmed within reach in ",
                                                 config_.verify_timeout_s, " s, twice"));
  }
  return SetTargetAside(now, seen_missing ? missing
                                          : absl::StrCat("not confirmed within ",
                                                         config_.verify_timeout_s, " s, twice"));
}

void TaskExecutor::RecordContact() {
  // Not for fly-roll robots: most of their blocks come in flight, above a crate whose top the map
  // lacks, and a contact stamped at the height mapped nearby kept them flying into it; measured
  // on the fly-roll bench, SR fell from 0.900 to 0.800 (docs/performance/mission.md, "Contacts").
  if (config_.max_contacts <= 0 || config_.multi_modal) return;
  // The way the robot was going: along the path's segment nearest it; its heading when the path
  // gives none.
  const Eigen::Vector2d here = pose_.position.head<2>();
  Eigen::Vector2d heading(std::cos(pose_.yaw), std::sin(pose_.yaw));
  const std::vector<Eigen::Vector3d>& path = progress_.path;
  double nearest_m = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d a = path[i].head<2>();
    const Eigen::Vector2d along = path[i + 1].head<2>() - a;
    if (along.norm() < 1e-6) continue;  // no direction
    const double distance_m = geometry::DistanceToSegment(here, a, path[i + 1].head<2>());
    if (distance_m < nearest_m) {
      nearest_m = distance_m;
      heading = along.normalized();
    }
  }
  if (path.size() == 1 && (path[0].head<2>() - here).norm() > 1e-6)
    heading = (path[0].head<2>() - here).normalized();
  constexpr double kHalfCellM = 0.025;
  Eigen::Vector3d contact = pose_.position;
  contact.head<2>() = here + (config_.robot_radius_m + kHalfCellM) * heading;
  contacts_.push_back(contact);
  if (contacts_.size() > static_cast<size_t>(config_.max_contacts))
    contacts_.erase(contacts_.begin());
}

std::vector<RobotCommand> TaskExecutor::Blocked(double now) {
  if (phase_ == Phase::kBackingOff)
    return ResumeAfterBackoff(now);  // cannot back off: re-plan from here
  const bool was_exploring = exploring();
  if (!blocked_goal_.has_value() ||
      (active_goal_ - *blocked_goal_).head<2>().norm() > config_.blocked_spot_radius_m) {
    blocked_goal_ = active_goal_;
    blocks_on_goal_ = 0;
  }
  ++blocks_on_goal_;
  const auto near_here = [&](const Eigen::Vector3d& spot) {
    return (spot - pose_.position).head<2>().norm() <= config_.blocked_spot_radius_m;
  };
  const int blocks_here =
      static_cast<int>(std::count_if(blocked_spots_.begin(), blocked_spots_.end(), near_here));
  const bool same_spot = blocks_here > 0;
  blocked_spots_.push_back(pose_.position);
  RecordContact();
  extra_clearance_m_ = std::min(extra_clearance_m_ + config_.blocked_clearance_step_m,
                                config_.blocked_clearance_max_m);
  // Fly-roll robots too: the multi-modal search inflates by the footprint and the clearance, so
  // the re-plan keeps the wider berth (it gave the goal up at once while it had no inflation).
  if (same_spot || blocks_on_goal_ >= config_.max_blocks_per_goal) {
    const std::string why =
        same_spot ? "robot blocked again where it was blocked before"
                  : absl::StrCat("robot blocked ", blocks_on_goal_, " times on the way");
    blocked_goal_.reset();
    blocks_on_goal_ = 0;
    if (was_exploring) {
      // Another route may reach it: the goal alone is spent, not its region.
      if (explore_goal_.has_value()) {
        SpendExploreGoal(*explore_goal_, /*unreachable=*/false);
        explore_goal_.reset();
        --progress_.explore_goals;  // never reached: no budget used
        if (config_.look_around_after_blocks_at_spot > 0 &&
            blocks_here >= config_.look_around_after_blocks_at_spot &&
            std::none_of(looked_around_at_blocks_.begin(), looked_around_at_blocks_.end(),
                         near_here)) {
          looked_around_at_blocks_.push_back(pose_.position);
          return Rotate(now, config_.look_around_rate_rps, config_.look_around_duration_s,
                        Phase::kExploreScan,
                        absl::StrCat("robot blocked ", blocks_here + 1,
                                     " times at this spot; looking around to map what blocks "
                                     "it"));
        }
        std::vector<RobotCommand> out = Explore(now);
        if (progress_.state == TaskState::kRunning)
          progress_.reason = absl::StrCat(progress_.reason, " (", why, ")");
        return out;
      }
      return ExplorationFailed(now, why);
    }
    if (progress_.target.has_value()) return SetTargetAside(now, why);
    return Replan(now, why);
  }
  if (config_.backoff_m <= 0.0) {  // the robot's own controller backs up (Nav2's BackUp)
    resume_exploring_ = was_exploring;
    return ResumeAfterBackoff(now);
  }
  return BackOff(now, was_exploring, "robot blocked; backing off to re-plan with more clearance");
}

std::vector<RobotCommand> TaskExecutor::BackOff(double now, bool resume_exploring,
                                                const std::string& reason) {
  // Back to the newest trail point (space the robot just drove through) at least backoff_m away
  // and behind the robot: it faces the obstacle, and its own recovery may have backed it up past
  // the newest points already.
  const Eigen::Vector3d heading(std::cos(pose_.yaw), std::sin(pose_.yaw), 0.0);
  std::vector<Eigen::Vector3d> path = {pose_.position};
  for (auto it = trail_.rbegin(); it != trail_.rend(); ++it) {
    const Eigen::Vector3d offset = *it - pose_.position;
    const double distance = offset.head<2>().norm();
    if (distance > 2.0 * config_.backoff_m) break;  // too far for a straight retreat
    if (distance >= config_.backoff_m && offset.head<2>().dot(heading.head<2>()) < 0.0) {
      path.push_back(*it);
      break;
    }
  }
  if (path.size() == 1 || (path.back() - pose_.position).head<2>().norm() < config_.backoff_m) {
    path = {pose_.position,
            pose_.position -
                config_.backoff_m * Eigen::Vector3d(std::cos(pose_.yaw), std::sin(pose_.yaw), 0.0)};
  }
  for (Eigen::Vector3d& point : path) point.z() = pose_.position.z();
  resume_exploring_ = resume_exploring;
  const Eigen::Vector3d back = path.back();
  return Navigate(now, back, std::move(path), pose_.yaw, 0.0, Phase::kBackingOff, reason);
}

std::vector<RobotCommand> TaskExecutor::RetraceTrail(double now, const std::string& reason) {
  // Regression (drift group, office_04 start 2): this retreat was BackOff's, whose length is the
  // blocked recovery's backoff_m, 0 by default, so "backing off" sent the robot to its own spot
  // and the task alternated it with looking around for the last 125 s of the budget.
  if (config_.no_path_retreat_m <= 0.0) return {};
  std::vector<Eigen::Vector3d> path = {pose_.position};
  double length = 0.0;
  std::size_t kept = trail_.size();
  for (auto it = trail_.rbegin(); it != trail_.rend() && length < config_.no_path_retreat_m; ++it) {
    const double step = (*it - path.back()).head<2>().norm();
    if (step > kTrailMaxStepM) break;  // a jump of the pose: the trail ends there
    --kept;
    if (step < 1e-3) continue;
    length += step;
    path.push_back(*it);
  }
  if (length < config_.no_path_retreat_m) return {};
  // What it retraced is no longer the way it came: the next retreat goes on from there.
  trail_.resize(kept + 1);
  for (Eigen::Vector3d& point : path) point.z() = pose_.position.z();
  resume_exploring_ = true;
  const Eigen::Vector3d back = path.back();
  return Navigate(now, back, std::move(path), YawTo(back), 0.0, Phase::kBackingOff, reason);
}

std::vector<RobotCommand> TaskExecutor::ResumeAfterBackoff(double now) {
  // A blocked navigation planned again is a re-plan: it counts toward max_replans.
  if (!resume_exploring_) return CountedReplan(now, "re-planning after backing off");
  if (!explore_goal_.has_value()) return Explore(now);  // after a fallback step with no path
  const Eigen::Vector3d goal = *explore_goal_;
  absl::StatusOr<std::vector<Eigen::Vector3d>> path = PlanPath(goal);
  if (absl::IsUnavailable(path.status())) return PauseExploring(now, path.status());
  if (!path.ok()) {
    phase_ = Phase::kExploring;
    return ExplorationFailed(now,
                             absl::StrCat("no path after backing off: ", path.status().message()));
  }
  return Navigate(now, goal, *std::move(path), YawTo(goal), 0.0, Phase::kExploring,
                  "exploring for the target (re-planned with more clearance)");
}

std::vector<RobotCommand> TaskExecutor::NoProgress(double now) {
  const std::string why = absl::StrCat("no progress for ", config_.progress_timeout_s, " s");
  switch (phase_) {
    case Phase::kExploring:
      return ExplorationFailed(now, why);
    case Phase::kVerifying:
      return VerifyTimedOut(now);
    case Phase::kBackingOff:
      return ResumeAfterBackoff(now);
    case Phase::kMoving:
      return Replan(now, why);
    default:
      return {};  // timed phases end by their own clocks
  }
}

void TaskExecutor::WatchProgress(double now) {
  const std::string key =
      absl::StrCat(progress_.subgoal_index, "/", static_cast<int>(phase_), "/",
                   progress_.target.has_value() ? progress_.target->object_id : -1);
  if (key != progress_key_ ||
      (pose_.position - progress_anchor_).head<2>().norm() >= config_.progress_distance_m) {
    progress_key_ = key;
    progress_anchor_ = pose_.position;
    progress_since_ = now;
  }
}

std::vector<RobotCommand> TaskExecutor::OnFeedback(double now, uint64_t command_id,
                                                   RobotFeedback feedback) {
  if (progress_.state != TaskState::kRunning || command_id != active_command_) return {};
  if (feedback == RobotFeedback::kBlocked) return Blocked(now);
  if (feedback != RobotFeedback::kGoalReached) {
    // The robot could not drive a fallback step (its local planner found no way): that
    // direction is not offered again.
    if (phase_ == Phase::kExploring && !explore_goal_.has_value())
      failed_fallback_steps_.push_back(active_goal_);
    return Replan(now, "robot reported failure");
  }
  if (phase_ == Phase::kMoving || phase_ == Phase::kExploring) {
    extra_clearance_m_ = 0.0;  // a goal reached: back to the normal clearance
    blocked_goal_.reset();
    blocks_on_goal_ = 0;
  }
  switch (phase_) {
    case Phase::kBackingOff:
      return ResumeAfterBackoff(now);
    case Phase::kExploring:
      set_aside_.clear();  // a new vantage point: targets set aside may be reachable from here
      explore_turned_from_.clear();
      if (current().type == SubgoalType::kExplore)
        return NextSubgoal(now, "exploration goal reached");
      if (LooksUpHere()) {
        looked_up_at_ = pose_.position;
        const double rate = config_.look_around_rate_rps;
        return Rotate(now, rate, 2.0 * M_PI / rate, Phase::kExploreScan,
                      "looking up at the exploration goal", LookUpTilt());
      }
      if (config_.explore_scan_duration_s > 0.0) {
        return Rotate(now, config_.look_around_rate_rps, config_.explore_scan_duration_s,
                      Phase::kExploreScan, "scanning at the exploration goal");
      }
      [[fallthrough]];  // no turn: the goal is spent as after one
    case Phase::kExploreScan:
      if (explore_goal_.has_value()) SpendExploreGoal(*explore_goal_, /*unreachable=*/false);
      return Explore(now);
    case Phase::kVerifying:
      return HoldToVerify(now);
    case Phase::kMoving:
    case Phase::kRotating:
    case Phase::kWaiting:
      return NextSubgoal(now, std::string(SubgoalTypeName(current().type)) + " done");
    case Phase::kIdle:
      return {};
  }
  return {};
}

std::vector<RobotCommand> TaskExecutor::OnPose(double now, const RobotPose& pose) {
  if (CheckRobotPose(pose, "pose").ok()) {  // keep the last good pose
    pose_ = pose;
    // Not while backing off: a retreat is not the way the robot came.
    if (phase_ != Phase::kBackingOff &&
        (trail_.empty() || (trail_.back() - pose_.position).head<2>().norm() >= kTrailSpacingM)) {
      trail_.push_back(pose_.position);
      if (trail_.size() > kTrailPoints) trail_.erase(trail_.begin());
    }
  }
  if (dependency_wait_.has_value() && progress_.state == TaskState::kPaused &&
      (now >= dependency_wait_->next_retry ||
       now - dependency_wait_->since >= config_.dependency_timeout_s)) {
    return RetryDependency(now);
  }
  if (progress_.state != TaskState::kRunning || phase_ == Phase::kIdle) return {};
  const bool searching = exploring() && current().type != SubgoalType::kExplore;
  if (searching && InEndgame(now) && TakeBestCandidate()) return GoToBestCandidate(now);
  WatchProgress(now);
  const bool timed =
      phase_ == Phase::kRotating || phase_ == Phase::kWaiting || phase_ == Phase::kExploreScan;
  if (!timed && now - progress_since_ >= config_.progress_timeout_s) {
    progress_since_ = now;
    return NoProgress(now);
  }
  if (phase_ == Phase::kExploring && explore_goal_.has_value() &&
      config_.explore_reselect_s > 0.0 && now - explore_chosen_at_ >= config_.explore_reselect_s)
    return ReselectExploreGoal(now);
  if (now < phase_deadline_) return {};
  switch (phase_) {
    case Phase::kRotating:
    case Phase::kWaiting:
    case Phase::kExploreScan:
      return OnFeedback(now, active_command_, RobotFeedback::kGoalReached);
    case Phase::kVerifying:
      return VerifyTimedOut(now);
    case Phase::kBackingOff:
      return ResumeAfterBackoff(now);
    default:
      return Replan(now, "motion timed out");
  }
}

std::vector<RobotCommand> TaskExecutor::OnSceneGraph(double now, const SceneGraph& graph) {
  return OnSceneGraph(now, std::make_shared<const SceneGraph>(graph));
}

std::vector<RobotCommand> TaskExecutor::OnSceneGraph(double now,
                                                     std::shared_ptr<const SceneGraph> graph) {
  // New detections of the located target: counted while the robot stands within reach of it.
  int fresh = 0;
  if (progress_.target.has_value()) {
    const SceneObject* before = graph_->FindObject(progress_.target->object_id);
    const SceneObject* after = graph->FindObject(progress_.target->object_id);
    if (before != nullptr && after != nullptr)
      fresh = std::max(0, after->detection_count - before->detection_count);
  }
  if (Ended(progress_.state)) return {};  // nothing to decide: no copy kept
  graph_ = std::move(graph);
  if (progress_.state != TaskState::kRunning) return {};
  if (progress_.target.has_value()) {
    if (const SceneObject* object = graph_->FindObject(progress_.target->object_id)) {
      progress_.target->position = object->position;  // the map refines its estimate
      // Mapping's label is a vote over the object's detections: a first detection under another
      // object's label (a detector confusion) is outvoted by the next ones. The new detections
      // then confirm that other object, not the target (home_01: a chair first seen as a
      // "potted plant" was approached and verified, by the fast path and, with the model, by
      // the slow path's answer for that label).
      const bool taken_by_label =
          progress_.target->path == ResolutionPath::kFast || progress_.target->named_by_its_label;
      if (taken_by_label && !ReadsAsTarget(*object)) {
        return ReleaseTarget(
            now, absl::StrCat("dropped: mapping now labels it \"", object->label, "\""));
      }
    }
  }
  if (std::optional<std::vector<RobotCommand>> reached = SuccessInView(now, fresh))
    return *std::move(reached);
  if (phase_ == Phase::kVerifying && progress_.target.has_value()) {
    const SceneObject* object = graph_->FindObject(progress_.target->object_id);
    // Mapping dropped it: missed far more often than seen, or seen once and never again.
    if (object == nullptr) {
      if (glancing_) return PassBy(now);
      return ReleaseTarget(now, "left the map while being verified: not there");
    }
    progress_.target->position = object->position;
    if (SeenMissing(*object)) return VerifyTimedOut(now, /*seen_missing=*/true);
    if (glancing_) {
      if (object->detection_count <= kSeenOnce) return {};
      glancing_ = false;  // seen again: drive to it
      return EnterSubgoal(now);
    }
    if (object->detection_count - progress_.target->detections_at_verify >=
        config_.verify_detections) {
      return CheckSuccessOrApproach(now);
    }
    return {};
  }
  const bool searching = exploring() && current().type != SubgoalType::kExplore;
  if (!searching) return {};
  if (TryResolve()) return EnterSubgoal(now);
  if (TakeLabelledCandidate()) return GoForCandidate(now);
  MaybeRequestModel();
  return {};
}

std::vector<RobotCommand> TaskExecutor::OnSlowDecision(double now, uint64_t graph_revision,
                                                       const SlowDecision& decision) {
  awaiting_model_ = false;
  if (decision.none_matched) {
    open_vocabulary_rejected_.insert(open_vocabulary_pending_.begin(),
                                     open_vocabulary_pending_.end());
  }
  open_vocabulary_pending_.clear();
  if (progress_.state != TaskState::kRunning || progress_.target.has_value()) return {};
  if (decision.action == SlowAction::kExplore || excluded_.count(decision.object_id) > 0 ||
      RuledOut(decision.object_id)) {
    progress_.reason = absl::StrCat("model: keep exploring (", decision.explanation, ")");
    return {};
  }
  // Set aside as unreachable from here: taking it again would fail again at once.
  if (set_aside_.count(decision.object_id) > 0) {
    progress_.reason = absl::StrCat("model names object ", decision.object_id,
                                    ", set aside until the next vantage point");
    return {};
  }
  const SceneObject* object = graph_->FindObject(decision.object_id);
  if (object == nullptr) {
    progress_.reason =
        absl::StrCat("model answer for revision ", graph_revision, " names a vanished object");
    return {};
  }
  // The model judged the label it was offered. If mapping has relabelled the object since, the
  // answer is about that old label (a road first detected as a "car" was named, then driven to
  // and verified as the car).
  if (auto offered = offered_labels_.find(object->id);
      offered != offered_labels_.end() && offered->second != object->label) {
    progress_.reason =
        absl::StrCat("model named object ", object->id, " as \"", offered->second,
                     "\"; mapping now labels it \"", object->label, "\": asking again");
    return {};
  }
  // A vision-verify answer is only a candidate: the VERIFY subgoal confirms or rejects it.
  progress_.target =
      LocatedTarget{object->id, object->position,      decision.confidence, ResolutionPath::kSlow,
                    0,          ReadsAsTarget(*object)};
  return exploring() ? EnterSubgoal(now) : std::vector<RobotCommand>{};
}

std::vector<RobotCommand> TaskExecutor::OnVisionVerdict(double now, bool confirmed) {
  if (progress_.state != TaskState::kRunning || phase_ != Phase::kVerifying) return {};
  if (confirmed) {
    return CheckSuccessOrApproach(now);
  }
  excluded_.insert(progress_.target->object_id);
  const std::string reason = absl::StrCat("object ", progress_.target->object_id, " not confirmed");
  progress_.target.reset();
  for (int i = 0; i < static_cast<int>(subgoals_.size()); ++i) {
    const SubgoalType type = subgoals_[static_cast<std::size_t>(i)].type;
    if (type == SubgoalType::kFind || (type == SubgoalType::kNavigate &&
                                       !subgoals_[static_cast<std::size_t>(i)].target.is_room)) {
      progress_.subgoal_index = i;
      break;
    }
  }
  return Replan(now, reason);
}

std::vector<RobotCommand> TaskExecutor::Pause() {
  if (dependency_wait_.has_value()) {
    // The operator's pause takes over: no retries, no timeout; Resume asks the planner again.
    dependency_wait_.reset();
    progress_.reason = "task paused";
    return {};
  }
  if (progress_.state != TaskState::kRunning) return {};
  return Halt(TaskState::kPaused, CommandKind::kHold, "task paused");
}

std::vector<RobotCommand> TaskExecutor::Resume(double now) {
  if (progress_.state != TaskState::kPaused) return {};
  if (dependency_wait_.has_value()) return RetryDependency(now);
  progress_.state = TaskState::kRunning;
  return EnterSubgoal(now);
}

std::vector<RobotCommand> TaskExecutor::Cancel(const std::string& reason) {
  if (finished()) return {};
  dependency_wait_.reset();
  std::vector<RobotCommand> stop = Fail(reason);
  progress_.state = TaskState::kCancelled;
  return stop;
}

void TaskExecutor::Restore(const TaskProgress& saved, const std::string& reason) {
  progress_.subgoal_index =
      std::clamp(saved.subgoal_index, 0, std::max(0, static_cast<int>(subgoals_.size()) - 1));
  progress_.replans = saved.replans;
  progress_.explore_goals = saved.explore_goals;
  progress_.model_requests = saved.model_requests;
  progress_.phase = saved.phase;
  progress_.reason = saved.reason;
  progress_.state = saved.state;
  if (finished()) return;
  progress_.state = TaskState::kPaused;
  progress_.reason = reason;
  phase_ = Phase::kIdle;
}

std::vector<RobotCommand> TaskExecutor::Retarget(double now, const TargetSpec& target,
                                                 bool exclude_current) {
  if (finished()) return {};
  if (exclude_current && progress_.target.has_value())
    excluded_.insert(progress_.target->object_id);
  progress_.target.reset();
  int first = -1;
  for (int i = 0; i < static_cast<int>(subgoals_.size()); ++i) {
    Subgoal& goal = subgoals_[static_cast<std::size_t>(i)];
    if (goal.target.empty() || goal.target.is_room) continue;
    goal.target = target;
    if (first < 0) first = i;
  }
  if (first >= 0 && first < progress_.subgoal_index) progress_.subgoal_index = first;
  progress_.replans = 0;
  progress_.reason = "target corrected";
  return progress_.state == TaskState::kRunning ? EnterSubgoal(now) : std::vector<RobotCommand>{};
}

}  // namespace semnav::reasoning
