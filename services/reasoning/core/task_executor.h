// Per-task state machine over the action primitives (seed 002, 3.2.5, LOVON): NAVIGATE (goal with
// yaw toward the target), APPROACH (stop 0.5 m away at 0.15 m/s), LOOK_AROUND (0.5 rad/s for 12 s),
// VERIFY (turn to face, hold, confirm by new detections or the vision model), BACKTRACK, EXPLORE,
// WAIT; with timeouts, re-planning on failure, and success = stopped within 1 m of a verified
// target (seed 004). Goal resolution uses the fast path; when it is not confident the executor
// keeps exploring and offers a slow-path model request that the server runs asynchronously
// (seed 000, 3.5: the model never blocks motion).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/fast_resolver.h"
#include "services/reasoning/core/navigation_interfaces.h"
#include "services/reasoning/core/robot_types.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/core/selective_grounding.h"
#include "services/reasoning/core/slow_answer.h"
#include "services/reasoning/core/subgoal.h"
#include "services/reasoning/core/topological_memory.h"

namespace semnav::reasoning {

struct ExecutorConfig {
  double approach_speed_mps = 0.15;      // APPROACH speed (LOVON)
  double look_around_rate_rps = 0.5;     // LOOK_AROUND angular speed
  double look_around_duration_s = 12.0;  // seed 002: 12 s ~ one turn
  // The turn at each reached exploration goal (0 = none: the next goal at once; VLFM and
  // ApexNav turn only at the start).
  double explore_scan_duration_s = 0.0;
  // The turn before the first exploration goal of a search (VLFM's initial spin; one turn at
  // 0.5 rad/s is 12.6 s); 0 = none. Off: it raised SPL but lowered SR over 80 episodes
  // (docs/performance/mission.md).
  double start_scan_duration_s = 0.0;
  // Targets that hang above a ground robot's default view: a wall clock at 1.8-2.2 m, where the
  // simulator's camera (0.88 m high, pitched 20 deg down, 24 deg half view) sees nothing higher
  // than 4 deg over the horizon, so the clock enters the image only from 12 m, twice the
  // detector's range. While searching for one, a robot that can tilt its camera
  // (Capabilities.camera_tilt_max_rad) turns once with the camera tilted up by look_up_tilt_rad
  // at the first exploration goal it reaches, and again at each goal look_up_every_m (about the
  // detector's range) from the last such turn. Empty = never; Habitat's agents have LOOK_UP.
  std::vector<std::string> look_up_labels = {"clock"};
  double look_up_tilt_rad = 0.5;
  double look_up_every_m = 4.0;
  double camera_tilt_max_rad = 0.0;   // the robot's (SetMobility); 0 = it cannot tilt
  double navigate_standoff_m = 1.0;   // NAVIGATE to an object stops this far from it
  double navigate_timeout_s = 120.0;  // per motion command before re-planning
  double verify_timeout_s = 10.0;     // VERIFY gives up (object rejected) after this
  int verify_detections = 2;          // new detections of the target that confirm it
  double wait_duration_s = 5.0;       // WAIT default
  double success_radius_m = 1.0;      // seed 004: success within 1 m of the target
  // Reach (success, verify, view points) is measured to the target's mapped extent, as Habitat
  // scores ObjectNav to the object's nearest point, not to its centre: a fridge seen from 0.8 m
  // has its centre 1.2 m away. Each half-extent counts up to this cap (a box grown by a wrong
  // merge cannot bring a far robot within reach); 0 = measured to the centre.
  double reach_extent_cap_m = 1.0;
  // An approach whose stand-off point is blocked stands at the free point nearest the object
  // within reach, unless the way there is longer than factor x its straight distance + slack:
  // then that point lies beyond a wall from the robot (a detour through a door) and seed 004's
  // line-of-sight point is taken instead.
  double reach_max_detour_factor = 2.0;
  double reach_detour_slack_m = 3.0;
  int max_replans = 3;                      // failures to reach one target before it is set aside
  double explore_exclusion_radius_m = 1.0;  // a failed exploration goal blocks frontiers this close
  // Exploration goals per search before giving up (failed ones do not count), for a task
  // without a time budget and for a plan's exploration step; a budgeted search runs to its end.
  int max_explore_goals = 30;
  // While driving to an exploration goal, planning is asked again this often (simulated or
  // robot seconds): a frontier seen from afar is cleared before the robot gets there, and a new
  // detection can make another one worth more (VLFM and ApexNav choose again every step). The
  // robot turns to the new goal when it lies more than explore_keep_radius_m from the old one
  // and from every goal it turned away from since it last reached one (no ping-pong between two
  // frontiers of similar worth). 0 = off: each goal is driven to its end.
  double explore_reselect_s = 2.0;
  double explore_keep_radius_m = 1.0;
  double fallback_explore_step_m = 3.0;  // without frontiers: step toward the least-explored sector
  // When no fallback step has a path from where the robot stands (a nook walled in by inflated
  // or misplaced walls), it first retraces the way it came, through space it drove, by this much
  // before it looks around. 0 = it only looks around.
  double no_path_retreat_m = 1.0;
  double min_explore_step_m = 0.5;  // an exploration goal whose path ends closer is spent unvisited
  // A rolling robot's exploration goals are cells its footprint stands on, reached with it
  // (SelectExplorationGoalRequest.robot_radius_m). Off: measured, it did not settle the fleet's
  // command tail and found fewer SEMANTIC_FRONTIER targets (docs/performance/mission.md).
  bool explore_with_footprint = false;
  bool model_available = false;    // offer slow-path model requests
  int grounding_max_objects = 15;  // ESCA budget of a slow-path request
  bool multi_modal = false;        // the robot can fly-roll: plan multi-modal paths
  RobotPlatform platform = RobotPlatform::kUnspecified;  // told to planning's exploration
  double robot_radius_m = 0.0;  // the robot's footprint radius for path planning
  // Paths keep this much more than the footprint from mapped obstacles (Nav2 inflates beyond the
  // inscribed radius too): mapped walls are off by a cell or two, and paths hug inflated edges.
  double path_clearance_m = 0.1;
  // A planner dependency gone (planning, or mapping behind it) pauses the task with the robot
  // holding: the planner is asked again this often, and the task fails after this long without it.
  double dependency_retry_s = 2.0;
  double dependency_timeout_s = 60.0;

  // Progress watchdog (Nav2's progress checker): in every driven phase the robot must move this
  // far from where it last made progress, or change phase, within progress_timeout_s; otherwise
  // the phase's recovery runs (exploration goal spent, target re-planned then set aside, VERIFY
  // fallback). Timed phases (look around, wait) end by their own clocks.
  double progress_timeout_s = 30.0;
  double progress_distance_m = 0.3;
  // Success in view: once the robot stands within success_radius_m - success_margin_m of the
  // located target (the map's estimate may be off a little) and the detector reports it
  // verify_detections more times from there, the task succeeds: no VERIFY turn, no timeout.
  double success_margin_m = 0.2;
  // VERIFY fallback after verify_timeout_s without verify_detections new detections: a target
  // within reach that was detected at least verify_accept_detections times in all is accepted
  // (close up the camera may not frame it); otherwise the robot steps back to verify_view_m from
  // it and looks once more; a second timeout sets the target aside (tried again from the next
  // exploration goal). Only the vision model's "no" rejects an object for good.
  int verify_accept_detections = 4;
  double verify_view_m = 0.8;
  // A VERIFY look ends before its timeout once mapping counts this many frames that should have
  // shown the target (SceneObject.miss_count: centre in view, within range, not hidden) and no new
  // detection of it came: the timeout's step (a second look, then ruled out or set aside) follows
  // at once, and it is not accepted. A detector with 90 % recall misses an object in view 3 times
  // running 0.1 % of the time; a false detection (the simulator's 0.05 per frame) is never seen
  // again, and waiting out two 10 s looks at each cost a fifth of a UAV's budget. 0 = off.
  int verify_rule_out_misses = 3;
  // Blocked recovery: after the robot reports BLOCKED it backs off backoff_m along the way it
  // came (0 = not: the robot's own controller backs up, as Nav2's BackUp and the simulator's
  // do; an extra executor retreat showed no benefit in the mission bench), and the next plans
  // keep blocked_clearance_step_m more clearance per block (at most
  // blocked_clearance_max_m, back to normal once a goal is reached). A goal the robot is blocked
  // on max_blocks_per_goal times, or again within blocked_spot_radius_m of a spot it was blocked
  // at, is given up: an exploration goal is spent, a target set aside.
  double backoff_m = 0.0;
  double blocked_clearance_step_m = 0.1;
  double blocked_clearance_max_m = 0.3;
  int max_blocks_per_goal = 2;
  double blocked_spot_radius_m = 0.5;
  // Blocked at one spot this many times before, exploring (the goal given up each time), the
  // robot first looks around once there: what stops it is missing from the map, so paths to any
  // goal keep starting into it (flyroll_02 start 2: 13 paths in a row began with the same step
  // into a crate's corner; after a look-around the path left the spot; docs/performance/
  // mission.md, "Blocked where the map has nothing"). 0 = never.
  int look_around_after_blocks_at_spot = 2;
  // Each block leaves a contact: the point the robot ran into, one footprint radius (plus
  // half a 5 cm cell) ahead of it along its path. The task's next path requests carry its last
  // max_contacts contacts, which planning marks as obstacles the map may lack (Nav2's collision
  // monitor and bumper layers serve the same end). Robots that plan on the ground only (not
  // multi_modal). 0 = none sent.
  int max_contacts = 16;
  // An exploration goal with no path (or the robot blocked on it) is set aside with the region
  // within unreachable_region_m around it: frontiers of the same unreachable pocket are not tried
  // one by one.
  double unreachable_region_m = 2.0;
  // The task's time budget, seconds from Start (0 = none: real robots run until cancelled).
  // A search with a budget runs until it is spent instead of max_explore_goals.
  // With less than endgame_s left and no accepted target, the robot goes to the best candidate
  // seen (the fast path's best label match, even below its threshold) instead of a new frontier.
  double time_budget_s = 0.0;
  double endgame_s = 40.0;
  // The endgame's candidate must name the target at least this well: 1 the same object, 0.5 one
  // name within the other ("table" / "coffee table", "cup" / "coffee cup", or the right object
  // with its asked colour unreported), 1/3 a sibling sharing a word ("coffee table" / "dining
  // table"), which the robot would otherwise verify and report as found (hold-out open office).
  double endgame_min_label_match = 0.5;
  // Without a model to ask (seed 002's slow path judges candidates below the fast path's
  // threshold), a candidate whose label matches at least this well (1 = the target's name or a
  // synonym) is driven to and verified instead of passed by: a target seen once at the edge of
  // the view has too few detections to pass the threshold. VERIFY sets it aside when it is not
  // confirmed. Above 1 = off.
  double approach_label_match = 1.0;
  // An object whose label reads as the target but whose appearance embedding lies further than
  // this (cosine) from the target's text embedding is not a candidate: its label is a detector
  // confusion (seed 002's embedding term; a road reported once as "car" keeps the road's look).
  // Without that check the slow path, which reads labels, named such objects, and the task
  // verified them or confirmed one (docs/performance/mission.md, "A label the appearance
  // contradicts"). Only when both embeddings are known; 0 = off. 0.5 suits an embedding space
  // where an object and its class name lie at cosine ~0.9 and other classes near 0 (the
  // simulator's; docs/simulation.md); a CLIP-scale space (matching pairs at ~0.3) needs its own.
  double min_appearance_agreement = 0.5;
  // Such a candidate detected only once is looked at again before the robot drives to it: the
  // robot turns to face it and holds for glance_s; one more detection and the approach starts,
  // none and it is passed by until the detector reports it again. A single detection is as often
  // a detector confusion or a false positive as the target (the simulator's 5 % of each), and
  // driving to one and verifying it cost 25-35 s (docs/performance/mission.md, "Glance").
  // 0 = off: drive to it at once.
  double glance_s = 2.0;
  // The task's search area (the operator's; unset = none). From outside it, fallback steps (no
  // goal from planning) lead back toward it: planning gives no goal to a robot outside the area,
  // so one step out led to the next and the UAV flew off the world. Inside, steps are as before.
  std::optional<SearchArea> search_area;
};

enum class TaskState { kRunning, kPaused, kSucceeded, kFailed, kCancelled };

// SUCCEEDED, FAILED or CANCELLED: the task will not move the robot again.
inline bool Ended(TaskState state) {
  return state == TaskState::kSucceeded || state == TaskState::kFailed ||
         state == TaskState::kCancelled;
}

// How the target was resolved: the scene-graph match (fast) or the language model's choice (slow).
enum class ResolutionPath { kFast, kSlow };

struct LocatedTarget {
  int64_t object_id = -1;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double confidence = 0.0;
  ResolutionPath path = ResolutionPath::kFast;
  int detections_at_verify = 0;
  // The model took it while mapping's label read as the target (not an open-vocabulary match):
  // like a fast-path target, it is dropped when later detections outvote that label.
  bool named_by_its_label = false;
  int misses_at_verify = 0;  // mapping's miss count when the current VERIFY look began
};

struct TaskProgress {
  TaskState state = TaskState::kRunning;
  int subgoal_index = 0;  // index into the subgoal list
  std::string phase;      // e.g. "navigating", "exploring", "verifying"
  std::string reason;     // latest decision or failure reason
  std::optional<LocatedTarget> target;
  int replans = 0;
  int explore_goals = 0;
  int model_requests = 0;
  std::vector<Eigen::Vector3d> path;  // the active navigate path
};

// A slow-path model call the server should run without blocking the executor.
struct ModelRequest {
  uint64_t graph_revision = 0;
  ResolveRequest request;  // prose + match_target task for the model proxy
  SceneGraph grounded;     // ESCA subgraph the answer must refer to
};

class TaskExecutor {
 public:
  // All pointers must outlive the executor; `memory` may be null.
  TaskExecutor(std::string instruction, std::vector<Subgoal> subgoals, const FastResolver* resolver,
               PathPlanner* planner, const TopologicalMemory* memory, ExecutorConfig config);

  // Each event returns the commands to send to the robot now (possibly none). `now` is monotonic
  // seconds.
  std::vector<RobotCommand> Start(double now, const RobotPose& pose);
  std::vector<RobotCommand> OnPose(double now, const RobotPose& pose);
  std::vector<RobotCommand> OnFeedback(double now, uint64_t command_id, RobotFeedback feedback);
  std::vector<RobotCommand> OnSceneGraph(double now, const SceneGraph& graph);
  // The same graph shared, not copied: the gateway hands one graph to every robot's task.
  std::vector<RobotCommand> OnSceneGraph(double now, std::shared_ptr<const SceneGraph> graph);
  std::vector<RobotCommand> OnSlowDecision(double now, uint64_t graph_revision,
                                           const SlowDecision& decision);
  std::vector<RobotCommand> OnVisionVerdict(double now, bool confirmed);
  // An operator's pause; during a dependency pause it stops the retries (the robot already holds).
  std::vector<RobotCommand> Pause();
  // Also retries the planner at once during a dependency pause.
  std::vector<RobotCommand> Resume(double now);
  std::vector<RobotCommand> Cancel(const std::string& reason);
  // Fails the task from outside with `reason` (the gateway could not relocalize the robot); the
  // robot stops. Nothing for a task that has ended.
  std::vector<RobotCommand> Abandon(const std::string& reason);
  // A task the gateway kept across its own restart (GatewayJournal): its subgoal, counters and
  // end state. A task that had not ended comes back PAUSED with `reason` and goes on from its
  // subgoal on Resume; nothing is commanded until then.
  void Restore(const TaskProgress& saved, const std::string& reason);
  // Replace the target of the remaining subgoals (multi-turn correction).
  std::vector<RobotCommand> Retarget(double now, const TargetSpec& target, bool exclude_current);

  // The robot's modality and footprint for planning (known once its session opened).
  void SetMobility(bool multi_modal, double robot_radius_m, RobotPlatform platform,
                   double camera_tilt_max_rad = 0.0) {
    config_.multi_modal = multi_modal;
    config_.robot_radius_m = robot_radius_m;
    config_.platform = platform;
    config_.camera_tilt_max_rad = camera_tilt_max_rad;
  }

  // The target's text embedding from the model proxy (fast path's embedding term); empty = the
  // seed's fallback (label match).
  void SetTextEmbedding(std::vector<float> embedding) { text_embedding_ = std::move(embedding); }

  // A pending slow-path request, handed out once.
  std::optional<ModelRequest> TakeModelRequest();
  const TaskProgress& progress() const { return progress_; }
  // The scene graph the executor decides on; empty once the task ended (not kept for GetTask).
  const SceneGraph& scene_graph() const { return *graph_; }
  const std::vector<Subgoal>& subgoals() const { return subgoals_; }
  bool finished() const;
  // Driving to, or looking around at, an exploration goal: the search has no object to go for.
  bool exploring() const { return phase_ == Phase::kExploring || phase_ == Phase::kExploreScan; }
  // PAUSED because the planner's dependency is gone (not by the operator or the session).
  bool waiting_for_dependency() const { return dependency_wait_.has_value(); }

 private:
  enum class Phase {
    kIdle,
    kMoving,
    kRotating,
    kWaiting,
    kExploring,
    kExploreScan,
    kVerifying,
    kBackingOff
  };

  std::vector<RobotCommand> EnterSubgoal(double now);
  std::vector<RobotCommand> NextSubgoal(double now, const std::string& reason);
  RobotCommand NewCommand(CommandKind kind, const std::string& reason);
  std::vector<RobotCommand> Halt(TaskState state, CommandKind kind, const std::string& reason);
  // An ended task drops what only a running search needs (the scene graph copy, search lists).
  void ReleaseSearchState();
  std::vector<RobotCommand> Fail(const std::string& reason);
  // Fails the task instead of sending a command that CheckCommand refused.
  std::vector<RobotCommand> Refuse(const absl::Status& refused);
  std::vector<RobotCommand> Replan(double now, const std::string& reason);
  // Counts the re-plan (failing or setting the target aside past max_replans) and plans again.
  std::vector<RobotCommand> CountedReplan(double now, const std::string& reason);
  // The planner answered UNAVAILABLE: hold and pause (once), retry from OnPose.
  std::vector<RobotCommand> PauseForDependency(double now, const absl::Status& unavailable);
  std::vector<RobotCommand> RetryDependency(double now);
  std::vector<RobotCommand> PauseExploring(double now, const absl::Status& unavailable);
  std::vector<RobotCommand> ExplorationFailed(double now, const std::string& reason);
  // Sets the target aside until the next vantage point (out of reach from here) and explores.
  std::vector<RobotCommand> SetTargetAside(double now, const std::string& reason);
  // Lets go of the target (the reason says why) and explores.
  std::vector<RobotCommand> ReleaseTarget(double now, const std::string& reason);
  // Ruled out by VERIFY and still where it was then.
  bool RuledOut(int64_t id) const;
  // Objects the resolver must not pick: excluded, set aside, ruled out, or with a label their
  // appearance contradicts.
  std::set<int64_t> SkippedObjects() const;
  // Labelled as the target, but its appearance embedding is far from the target's text embedding
  // (min_appearance_agreement).
  bool AppearanceContradicts(const SceneObject& object) const;
  // The object's current label still matches the active target.
  bool ReadsAsTarget(const SceneObject& object) const;
  std::vector<RobotCommand> Search(double now);
  // With `reach_target`, a goal held or walled in by obstacles is replaced first by the reachable
  // free point nearest the target within reach (ReachRadius), then by seed 004's point on the
  // line of sight; without it, by the line-of-sight point only.
  absl::StatusOr<std::vector<Eigen::Vector3d>> PlanPath(
      const Eigen::Vector3d& goal, const std::optional<Eigen::Vector3d>& reach_target = {});
  // Half of the located target's mapped footprint, each half capped at reach_extent_cap_m (zero
  // when the map gives no size).
  Eigen::Vector2d TargetHalfExtent() const;
  // How far from the located target's centre a standing point may lie and still be within
  // success_radius_m - success_margin_m of its capped extent.
  double ReachRadius() const;
  std::vector<RobotCommand> Explore(double now);
  std::vector<RobotCommand> MoveTo(double now, const Eigen::Vector3d& goal, double yaw,
                                   double speed, Phase phase, const std::string& reason,
                                   const std::optional<Eigen::Vector3d>& reach_target = {});
  std::vector<RobotCommand> Navigate(double now, const Eigen::Vector3d& goal,
                                     std::vector<Eigen::Vector3d> path, double yaw, double speed,
                                     Phase phase, const std::string& reason);
  std::vector<RobotCommand> Rotate(double now, double rate, double duration, Phase phase,
                                   const std::string& reason, double camera_tilt_rad = 0.0);
  // The camera tilt for the active target: look_up_tilt_rad within the robot's limit for a
  // label in look_up_labels, else 0.
  double LookUpTilt() const;
  // A turn with the camera tilted up is due here (look_up_labels, look_up_every_m).
  bool LooksUpHere() const;
  std::vector<RobotCommand> Hold(double now, double duration, const std::string& reason);
  std::vector<RobotCommand> CheckSuccessOrApproach(double now);
  // Horizontal distance from `point` to the located target's mapped extent (reach_extent_cap_m).
  double DistanceToTarget(const Eigen::Vector3d& point) const;
  // The located target is reached: the subgoals about it are done.
  std::vector<RobotCommand> TargetReached(double now, const std::string& reason);
  // Success in view: within reach of the located target and seeing it; nullopt = not yet.
  std::optional<std::vector<RobotCommand>> SuccessInView(double now, int fresh_detections);
  // VERIFY: the robot reached its view of the target; it holds for the rest of the window.
  std::vector<RobotCommand> HoldToVerify(double now);
  // The current VERIFY look starts counting the target's detections and misses from here.
  void StartVerifyLook(const SceneObject* object);
  // Mapping counted verify_rule_out_misses frames that should have shown the target since the
  // look began, and none detected it.
  bool SeenMissing(const SceneObject& object) const;
  // VERIFY ran out of time without enough new detections, or the target was seen missing:
  // accept (only on a timeout), look again, or set aside.
  std::vector<RobotCommand> VerifyTimedOut(double now, bool seen_missing = false);
  // The robot reported BLOCKED: back off and re-plan with more clearance, or give the goal up.
  std::vector<RobotCommand> Blocked(double now);
  // Adds the point the robot ran into to contacts_ (ExecutorConfig::max_contacts).
  void RecordContact();
  // Drive back along the recent trail (known free space); then ResumeAfterBackoff.
  std::vector<RobotCommand> BackOff(double now, bool resume_exploring, const std::string& reason);
  // Back along the trail by no_path_retreat_m, then explore again; empty when the trail is
  // shorter than that.
  std::vector<RobotCommand> RetraceTrail(double now, const std::string& reason);
  std::vector<RobotCommand> ResumeAfterBackoff(double now);
  // The watchdog fired: the phase's recovery.
  std::vector<RobotCommand> NoProgress(double now);
  void WatchProgress(double now);
  // Spends an exploration goal; an unreachable one with the region around it.
  void SpendExploreGoal(const Eigen::Vector3d& goal, bool unreachable);
  // The robot is inside the search area, or the fallback step to `target` ends nearer to it.
  bool StepKeepsToTheArea(const Eigen::Vector3d& target) const;
  // The fast path's best candidate (even below its threshold), skipping excluded and set-aside
  // objects.
  std::optional<ScoredObject> BestCandidate() const;
  // Endgame: with little budget left, the best candidate seen becomes the target.
  bool TakeBestCandidate();
  // No model: a candidate matching the target's label (approach_label_match) becomes the target.
  bool TakeLabelledCandidate();
  // Goes for the target just located: a glance first when it was detected only once
  // (glance_s), else the subgoal's approach.
  std::vector<RobotCommand> GoForCandidate(double now);
  // The glance's window ended without a new detection: the candidate is passed by.
  std::vector<RobotCommand> PassBy(double now);
  bool InEndgame(double now) const;
  std::vector<RobotCommand> GoToBestCandidate(double now);
  std::vector<RobotCommand> FallbackStep(double now);
  // On the way to an exploration goal: planning's best goal now, and a turn to it when it moved
  // (explore_reselect_s).
  std::vector<RobotCommand> ReselectExploreGoal(double now);
  // The exploration request from here, with the spent goals and the goal to keep (none: the
  // strategy's best).
  ExplorationQuery ExplorationRequest(const std::optional<Eigen::Vector3d>& keep_goal) const;
  // The clearance PlanPath asks for beyond the footprint.
  double PathClearance() const;
  // The path to an exploration goal takes the robot at least min_explore_step_m away (an empty
  // path: the robot plans locally to the goal).
  bool LeadsAway(const absl::StatusOr<std::vector<Eigen::Vector3d>>& path,
                 const Eigen::Vector3d& goal) const;
  bool TryResolve();
  void MaybeRequestModel();
  const Subgoal& current() const {
    return subgoals_[static_cast<std::size_t>(progress_.subgoal_index)];
  }
  const TargetSpec& ActiveTarget() const;
  double YawTo(const Eigen::Vector3d& point) const;

  std::string instruction_;
  std::vector<Subgoal> subgoals_;
  const FastResolver* resolver_;
  PathPlanner* planner_;
  const TopologicalMemory* memory_;
  ExecutorConfig config_;

  TaskProgress progress_;
  Phase phase_ = Phase::kIdle;
  RobotPose pose_;
  std::shared_ptr<const SceneGraph> graph_ = EmptySceneGraph();
  std::set<int64_t> excluded_;
  std::vector<float> text_embedding_;
  // Targets the robot failed to reach; retried once it reached another exploration goal.
  std::set<int64_t> set_aside_;
  // Targets VERIFY ruled out from within reach, with where the map had them then.
  std::map<int64_t, Eigen::Vector3d> ruled_out_at_;
  std::optional<Eigen::Vector3d> explore_goal_;  // the active exploration goal from planning
  double explore_chosen_at_ = 0.0;               // when it was last chosen or confirmed
  // Goals turned away from since the last one reached: not turned back to (hysteresis).
  std::vector<Eigen::Vector3d> explore_turned_from_;
  // Where the last turn with the camera tilted up was (look_up_every_m counts from it).
  std::optional<Eigen::Vector3d> looked_up_at_;
  // Where the robot stood when a verified target was last found too far away: a second verdict
  // from the same spot means the approach cannot get closer.
  std::optional<Eigen::Vector3d> too_far_at_;
  // Exploration goals the robot failed to reach or already scanned from: not offered again (a
  // frontier that survives a visit and a full turn cannot be cleared from there).
  std::vector<Eigen::Vector3d> spent_explore_goals_;
  // Recent positions (every 0.25 m), newest last: backing off retraces them.
  std::vector<Eigen::Vector3d> trail_;
  // Progress watchdog: where and when the robot last moved or changed phase.
  Eigen::Vector3d progress_anchor_ = Eigen::Vector3d::Zero();
  double progress_since_ = 0.0;
  std::string progress_key_;
  // Success in view: detections of the target seen while within reach.
  int64_t close_target_ = -1;
  int close_detections_ = 0;
  // VERIFY: the target got its second look already.
  int64_t second_look_target_ = -1;
  // Glance (glance_s): VERIFY's turn and hold, held to a single-detection candidate before any
  // approach. Candidates passed by, with their detection count then: skipped until it grows.
  bool glancing_ = false;
  std::map<int64_t, int> passed_by_;
  // Blocked recovery.
  Eigen::Vector3d active_goal_ = Eigen::Vector3d::Zero();  // goal of the last navigate command
  std::optional<Eigen::Vector3d> blocked_goal_;
  int blocks_on_goal_ = 0;
  std::vector<Eigen::Vector3d> blocked_spots_;
  std::vector<Eigen::Vector3d> looked_around_at_blocks_;  // once per spot
  std::vector<Eigen::Vector3d> contacts_;  // where blocks stopped the robot, oldest first
  double extra_clearance_m_ = 0.0;
  bool resume_exploring_ = false;
  // Fallback steps with no path: other directions are tried next.
  std::vector<Eigen::Vector3d> failed_fallback_steps_;
  bool last_fallback_backed_off_ = false;
  bool start_scan_done_ = false;  // the search's first look around (start_scan_duration_s)
  double start_time_ = 0.0;
  bool endgame_taken_ = false;
  uint64_t next_command_id_ = 1;
  uint64_t active_command_ = 0;
  CommandKind active_kind_ = CommandKind::kHold;
  double phase_deadline_ = 0.0;
  uint64_t requested_revision_ = 0;
  // Open vocabulary: the classes last shown to the model (and how many objects were skipped
  // then); a newer graph with the same classes is not asked about again.
  std::string open_vocabulary_asked_;
  // Open vocabulary: the classes of the request in flight, and those the model said are not the
  // target (not shown again, so a class seen later gets its turn within the grounding budget).
  std::set<std::string> open_vocabulary_pending_;
  std::set<std::string> open_vocabulary_rejected_;
  // The label of each object the request in flight offered: the model judged that label.
  std::map<int64_t, std::string> offered_labels_;
  bool awaiting_model_ = false;
  std::optional<ModelRequest> pending_request_;
  struct DependencyWait {
    std::string dependency;  // "planning" or "mapping"
    double since = 0.0;      // first UNAVAILABLE answer
    double next_retry = 0.0;
  };
  std::optional<DependencyWait> dependency_wait_;
};

std::string_view TaskStateName(TaskState state);

}  // namespace semnav::reasoning
