#include "services/reasoning/core/relocalization_loop.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include "absl/strings/str_format.h"
#include "services/reasoning/core/fast_resolver.h"

namespace semnav::reasoning {
namespace {

double Wrap(double angle) { return std::remainder(angle, 2.0 * M_PI); }

RobotCommand Rotate(uint64_t id, double rate, double duration, const std::string& reason) {
  RobotCommand command;
  command.kind = CommandKind::kRotate;
  command.id = id;
  command.angular_speed = rate;
  command.duration_s = duration;
  command.reason = reason;
  return command;
}

RelocalizationAction Hold(uint64_t id, const std::string& reason) {
  RelocalizationAction hold;
  hold.kind = RelocalizationAction::Kind::kCommand;
  hold.command.kind = CommandKind::kHold;
  hold.command.id = id;
  hold.command.reason = reason;
  return hold;
}

}  // namespace

Eigen::Vector3d PlanarTransform::Apply(const Eigen::Vector3d& point) const {
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  return Eigen::Vector3d(c * point.x() - s * point.y(), s * point.x() + c * point.y(), point.z()) +
         translation;
}

namespace {

// a after b: p -> a(b(p)).
PlanarTransform Compose(const PlanarTransform& a, const PlanarTransform& b) {
  return PlanarTransform{a.Apply(b.translation), Wrap(a.yaw + b.yaw)};
}

}  // namespace

RobotPose PlanarTransform::Apply(const RobotPose& pose) const {
  return RobotPose{Apply(pose.position), Wrap(pose.yaw + yaw)};
}

PlanarTransform PlanarTransform::Inverse() const {
  PlanarTransform inverse;
  inverse.yaw = Wrap(-yaw);
  inverse.translation =
      -PlanarTransform{Eigen::Vector3d::Zero(), -yaw}.Apply(translation);  // -R^T t
  return inverse;
}

RelocalizationLoop::RelocalizationLoop(RelocalizationLoopConfig config)
    : config_(config),
      max_speed_mps_(config.default_speed_mps),
      max_yaw_rate_rps_(config.default_yaw_rate_rps) {}

void RelocalizationLoop::SetLimits(double max_speed_mps, double max_yaw_rate_rps) {
  max_speed_mps_ = max_speed_mps > 0.0 ? max_speed_mps : config_.default_speed_mps;
  max_yaw_rate_rps_ = max_yaw_rate_rps > 0.0 ? max_yaw_rate_rps : config_.default_yaw_rate_rps;
}

void RelocalizationLoop::OnSessionOpened() { last_state_time_.reset(); }

bool RelocalizationLoop::Jumped(double now, const RobotPose& odom_pose) const {
  if (!last_state_time_.has_value()) return false;
  const double dt = std::max(0.0, now - *last_state_time_);
  const double moved = (odom_pose.position - last_pose_.position).head<2>().norm();
  const double turned = std::abs(Wrap(odom_pose.yaw - last_pose_.yaw));
  return moved > max_speed_mps_ * dt + config_.jump_distance_m ||
         turned > max_yaw_rate_rps_ * dt + config_.jump_yaw_rad;
}

std::vector<RelocalizationAction> RelocalizationLoop::OnState(double now,
                                                              const RobotPose& odom_pose,
                                                              LocalizationReport report,
                                                              const SceneGraph& graph,
                                                              bool task_running) {
  const bool jumped = Jumped(now, odom_pose);
  const LocalizationReport previous = reported_;
  reported_ = report;
  last_state_time_ = now;
  last_pose_ = odom_pose;
  pose_ = odom_pose;
  switch (phase_) {
    case Phase::kLookingAround:
      if (call_in_flight_ && now < call_deadline_) return {};  // the turn's query answers first
      call_in_flight_ = false;
      if (now >= phase_deadline_) return LookAround(now, graph);
      return QueryDuringTurn(now, graph);
    case Phase::kAwaitingAnswer:
      if (now >= phase_deadline_) {
        return AttemptFailed(now,
                             absl::StrFormat("relocalization did not answer within %.1f s",
                                             config_.answer_timeout_s),
                             graph);
      }
      return {};
    case Phase::kAwaitingRefinement:
      if (now >= phase_deadline_ && global_pending_) {
        global_pending_ = false;
        return AttemptFailed(
            now,
            absl::StrFormat("%s; the global scan match did not answer within %.1f s", failed_why_,
                            config_.answer_timeout_s),
            graph);
      }
      if (now >= phase_deadline_) {
        return Apply(now, pending_,
                     absl::StrFormat("scan refinement did not answer within %.1f s",
                                     config_.answer_timeout_s));
      }
      return {};
    case Phase::kTracking:
      break;
  }
  if (jumped) return Start(now, "pose jumped beyond the commanded motion", graph);
  if (report != LocalizationReport::kOk &&
      (previous == LocalizationReport::kOk || now - last_ended_ >= config_.retrigger_after_s)) {
    return Start(
        now, report == LocalizationReport::kLost ? "robot reports LOST" : "robot reports UNCERTAIN",
        graph);
  }
  if (!trusted_ && task_running) return Start(now, "a task started on an untrusted pose", graph);
  return {};
}

std::vector<RelocalizationAction> RelocalizationLoop::OnRequest(double now,
                                                                const std::string& reason,
                                                                const SceneGraph& graph) {
  if (phase_ != Phase::kTracking) return {};
  return Start(now, reason.empty() ? "operator request" : "operator request: " + reason, graph);
}

std::vector<RelocalizationAction> RelocalizationLoop::Start(double now, const std::string& trigger,
                                                            const SceneGraph& graph) {
  trigger_ = trigger;
  attempt_ = 0;
  ForgetObjects();
  for (const SceneObject& object : graph.objects) {
    if (!object.embedding.empty()) map_objects_.push_back(object);
  }
  paused_task_ = true;  // the hub pauses only a running task; resuming a task it did not pause is a
                        // no-op there
  std::vector<RelocalizationAction> actions;
  RelocalizationAction pause;
  pause.kind = RelocalizationAction::Kind::kPauseTask;
  pause.message = absl::StrFormat("relocalizing: %s", trigger);
  actions.push_back(pause);
  std::vector<RelocalizationAction> look = LookAround(now, graph);
  actions.insert(actions.end(), look.begin(), look.end());
  return actions;
}

// Starts a look-around (phase kTracking or a failed attempt), or, when one has just ended,
// sends what it saw to relocalization.
std::vector<RelocalizationAction> RelocalizationLoop::LookAround(double now,
                                                                 const SceneGraph& graph) {
  std::vector<RelocalizationAction> actions;
  if (phase_ == Phase::kLookingAround) {
    turn_objects_.clear();
    std::unordered_set<int64_t> on_the_map;
    for (const SceneObject& m : map_objects_) on_the_map.insert(m.id);
    for (const SceneObject& object : graph.objects) {
      if (on_the_map.count(object.id) == 0 && !object.embedding.empty() &&
          object.detection_count >= config_.min_object_detections) {
        turn_objects_.push_back(object);
      }
    }
    std::vector<ObservedObject> observed = Observed(graph);
    if (static_cast<int>(observed.size()) < config_.min_observed_objects) {
      return FailedOrGlobal(now,
                            absl::StrFormat("the look-around saw %d objects, %d needed",
                                            observed.size(), config_.min_observed_objects),
                            graph);
    }
    actions.push_back(Hold(next_command_id_++, "relocalizing: waiting for the answer"));
    RelocalizationAction call;
    call.kind = RelocalizationAction::Kind::kRelocalize;
    call.observed = std::move(observed);
    call.message = absl::StrFormat("%d observed objects", call.observed.size());
    actions.push_back(std::move(call));
    phase_ = Phase::kAwaitingAnswer;
    phase_deadline_ = now + config_.answer_timeout_s;
    return actions;
  }
  ++attempt_;
  baseline_.clear();
  for (const SceneObject& object : graph.objects) baseline_[object.id] = object.detection_count;
  // The same angle at the robot's own limit when that is lower.
  turn_rate_ = std::min(config_.look_around_rate_rps, max_yaw_rate_rps_);
  turn_duration_ = config_.look_around_duration_s * config_.look_around_rate_rps / turn_rate_;
  RelocalizationAction rotate;
  rotate.kind = RelocalizationAction::Kind::kCommand;
  rotate.command = Rotate(next_command_id_++, turn_rate_, turn_duration_,
                          absl::StrFormat("relocalizing: looking around (attempt %d)", attempt_));
  actions.push_back(rotate);
  phase_ = Phase::kLookingAround;
  phase_deadline_ = now + turn_duration_;
  call_in_flight_ = false;
  next_query_ = now + config_.query_interval_s;
  last_query_size_ = 0;
  return actions;
}

std::vector<RelocalizationAction> RelocalizationLoop::QueryDuringTurn(double now,
                                                                      const SceneGraph& graph) {
  if (config_.query_interval_s <= 0.0 || now < next_query_) return {};
  std::vector<ObservedObject> observed = Observed(graph);
  if (static_cast<int>(observed.size()) < config_.min_observed_objects ||
      observed.size() <= last_query_size_) {
    return {};  // not enough yet, or nothing the last query did not have
  }
  next_query_ = now + config_.query_interval_s;
  last_query_size_ = observed.size();
  call_in_flight_ = true;
  call_deadline_ = now + config_.answer_timeout_s;
  RelocalizationAction call;
  call.kind = RelocalizationAction::Kind::kRelocalize;
  call.message = absl::StrFormat("%d observed objects (turning)", observed.size());
  call.observed = std::move(observed);
  return {std::move(call)};
}

std::vector<ObservedObject> RelocalizationLoop::Observed(const SceneGraph& graph) const {
  // Objects first found during the look-around carry only what the robot saw from here (in the
  // frame it believes); objects seen again may mix older observations, so they come second.
  const PlanarTransform odom_from_map = map_from_odom_.Inverse();
  std::vector<std::pair<int, ObservedObject>> ranked;  // (0 = new, 1 = seen again), object
  for (const SceneObject& object : graph.objects) {
    auto before = baseline_.find(object.id);
    const bool fresh = before == baseline_.end();
    if (!fresh && object.detection_count <= before->second) continue;
    if (object.embedding.empty()) continue;
    ObservedObject observed;
    observed.object_id = object.id;
    observed.position = odom_from_map.Apply(object.position);
    observed.scale_m = object.scale_m() > 0.0 ? object.scale_m() : config_.default_object_scale_m;
    observed.embedding = object.embedding;
    observed.observations = fresh ? std::max(1, object.detection_count)
                                  : std::max(1, object.detection_count - before->second);
    if (observed.observations < config_.min_object_detections) continue;
    ranked.emplace_back(fresh ? 0 : 1, std::move(observed));
  }
  const Eigen::Vector3d here = pose_.position;
  std::stable_sort(ranked.begin(), ranked.end(), [&here](const auto& a, const auto& b) {
    if (a.first != b.first) return a.first < b.first;
    return (a.second.position - here).squaredNorm() < (b.second.position - here).squaredNorm();
  });
  // With enough new objects, re-seen ones (possibly fused with pre-loss observations) stay out.
  int fresh_count = 0;
  for (const auto& entry : ranked) fresh_count += entry.first == 0 ? 1 : 0;
  std::vector<ObservedObject> out;
  for (auto& entry : ranked) {
    if (entry.first == 1 && fresh_count >= config_.min_observed_objects) break;
    if (static_cast<int>(out.size()) >= config_.max_observed_objects) break;
    out.push_back(std::move(entry.second));
  }
  return out;
}

std::string RelocalizationLoop::Rejection(
    const absl::StatusOr<RelocalizationAnswer>& answer) const {
  if (!answer.ok()) {
    return absl::StrFormat("relocalization failed: %s", answer.status().message());
  }
  if (!answer->reliable) {
    return absl::StrFormat("relocalization answer not reliable (%d inliers, rms %.2f m)",
                           answer->inliers, answer->rms_residual_m);
  }
  if (reported_ != LocalizationReport::kOk) {
    const RobotPose before = map_from_odom_.Apply(pose_);
    const RobotPose after = answer->map_from_odom.Apply(pose_);
    const double moved = (after.position - before.position).head<2>().norm();
    const double turned = std::abs(Wrap(after.yaw - before.yaw));
    if (moved < config_.confirming_answer_m && turned < config_.confirming_answer_rad) {
      return absl::StrFormat(
          "the answer confirms the pose the robot reports %s (moves it %.2f m, %.1f deg; %d "
          "inliers, rms %.2f m): the look-around matched itself?",
          reported_ == LocalizationReport::kLost ? "LOST" : "UNCERTAIN", moved,
          turned * 180.0 / M_PI, answer->inliers, answer->rms_residual_m);
    }
  }
  return "";
}

std::vector<RelocalizationAction> RelocalizationLoop::OnAnswer(
    double now, const absl::StatusOr<RelocalizationAnswer>& answer) {
  if (phase_ == Phase::kLookingAround) {  // the answer to a query during the turn
    if (!call_in_flight_) return {};
    call_in_flight_ = false;
    if (!Rejection(answer).empty()) return {};  // the turn goes on; its end asks again
    return Recovered(now, *answer, /*stop_turning=*/true);
  }
  if (phase_ != Phase::kAwaitingAnswer) return {};  // late answer of an attempt that timed out
  const std::string why = Rejection(answer);
  if (!why.empty()) return FailedOrGlobal(now, why, SceneGraph{});
  return Recovered(now, *answer, /*stop_turning=*/false);
}

std::vector<RelocalizationAction> RelocalizationLoop::Recovered(double now,
                                                                const RelocalizationAnswer& answer,
                                                                bool stop_turning) {
  std::vector<RelocalizationAction> actions;
  if (stop_turning) {
    actions.push_back(Hold(next_command_id_++, "relocalized: the look-around ends"));
  }
  if (!config_.refine_with_scan) {
    std::vector<RelocalizationAction> applied = Apply(now, answer, "");
    actions.insert(actions.end(), applied.begin(), applied.end());
    return actions;
  }
  pending_ = answer;
  phase_ = Phase::kAwaitingRefinement;
  phase_deadline_ = now + config_.answer_timeout_s;
  RelocalizationAction refine;
  refine.kind = RelocalizationAction::Kind::kRefine;
  // The robot's frames carry the pose it reports: the current correction applied to odometry.
  refine.map_from_odom = Compose(answer.map_from_odom, map_from_odom_.Inverse());
  refine.message =
      absl::StrFormat("refining the answer (%d inliers) against the walls", answer.inliers);
  actions.push_back(std::move(refine));
  return actions;
}

std::vector<RelocalizationAction> RelocalizationLoop::FailedOrGlobal(double now,
                                                                     const std::string& why,
                                                                     const SceneGraph& graph) {
  if (!config_.refine_with_scan || !config_.global_scan_match) {
    return AttemptFailed(now, why, graph);
  }
  failed_why_ = why;
  global_pending_ = true;
  phase_ = Phase::kAwaitingRefinement;
  phase_deadline_ = now + config_.answer_timeout_s;
  RelocalizationAction match;
  match.kind = RelocalizationAction::Kind::kRefine;
  match.global = true;
  match.message = absl::StrFormat(
      "no answer from objects (%s): matching the look-around against "
      "the whole map",
      why);
  return {std::move(match)};
}

std::vector<RelocalizationAction> RelocalizationLoop::OnRefinement(
    double now, const absl::StatusOr<ScanRefinement>& refinement) {
  if (phase_ != Phase::kAwaitingRefinement) return {};  // late: the coarse answer was applied
  if (global_pending_) {
    global_pending_ = false;
    if (!refinement.ok()) {
      return AttemptFailed(now,
                           absl::StrFormat("%s; the global scan match failed: %s", failed_why_,
                                           refinement.status().message()),
                           SceneGraph{});
    }
    // A refused match may still be taken when the turn's objects confirm it.
    const bool may_confirm = !refinement->refined && config_.confirm_min_objects > 0 &&
                             refinement->score >= config_.confirm_min_score &&
                             refinement->ray_conflicts <= config_.confirm_max_ray_conflicts;
    const int confirming = may_confirm ? ConfirmingObjects(refinement->map_from_reported) : 0;
    std::string how;
    if (refinement->refined) {
      how = absl::StrFormat("global scan match (score %.2f, the best other pose %.2f) after: %s",
                            refinement->score, refinement->runner_up_score, failed_why_);
    } else if (may_confirm && confirming >= config_.confirm_min_objects) {
      how = absl::StrFormat(
          "global scan match confirmed by %d objects (score %.2f, the best other pose %.2f, rays "
          "through walls %.0f %%) after: %s",
          confirming, refinement->score, refinement->runner_up_score,
          100.0 * refinement->ray_conflicts, failed_why_);
    } else {
      // Where the best pose would put the robot, so that a log can tell a right answer refused
      // from a wrong one.
      const RobotPose best = Compose(refinement->map_from_reported, map_from_odom_).Apply(pose_);
      return AttemptFailed(
          now,
          absl::StrFormat("%s; no unique global scan match (score %.2f at (%.2f, %.2f, %.0f deg), "
                          "the best other pose %.2f, rays through walls %.0f %%)",
                          failed_why_, refinement->score, best.position.x(), best.position.y(),
                          std::remainder(best.yaw, 2.0 * M_PI) * 180.0 / M_PI,
                          refinement->runner_up_score, 100.0 * refinement->ray_conflicts),
          SceneGraph{});
    }
    RelocalizationAnswer found;
    found.map_from_odom = Compose(refinement->map_from_reported, map_from_odom_);
    found.reliable = true;
    return Apply(now, found, how);
  }
  if (!refinement.ok()) {
    return Apply(now, pending_,
                 absl::StrFormat("scan refinement failed: %s", refinement.status().message()));
  }
  if (!refinement->refined) {
    return Apply(now, pending_,
                 absl::StrFormat("scan refinement kept the answer (score %.2f, at the answer "
                                 "%.2f)",
                                 refinement->score, refinement->coarse_score));
  }
  RelocalizationAnswer refined = pending_;
  refined.map_from_odom = Compose(refinement->map_from_reported, map_from_odom_);
  const PlanarTransform change = Compose(refined.map_from_odom, pending_.map_from_odom.Inverse());
  return Apply(now, refined,
               absl::StrFormat("scan-refined by %.2f m, %.1f deg (score %.2f -> %.2f)",
                               change.translation.head<2>().norm(), change.yaw * 180.0 / M_PI,
                               refinement->coarse_score, refinement->score));
}

void RelocalizationLoop::ForgetObjects() {
  map_objects_ = {};
  turn_objects_ = {};
}

int RelocalizationLoop::ConfirmingObjects(const PlanarTransform& map_from_reported) const {
  std::vector<bool> used(turn_objects_.size(), false);
  int confirming = 0;
  for (const SceneObject& on_map : map_objects_) {
    for (size_t i = 0; i < turn_objects_.size(); ++i) {
      if (used[i]) continue;
      const Eigen::Vector3d at = map_from_reported.Apply(turn_objects_[i].position);
      if ((at - on_map.position).head<2>().norm() > config_.confirm_distance_m) continue;
      if (Cosine(turn_objects_[i].embedding, on_map.embedding) < config_.confirm_min_cosine) {
        continue;
      }
      used[i] = true;
      ++confirming;
      break;
    }
  }
  return confirming;
}

std::vector<RelocalizationAction> RelocalizationLoop::Apply(double now,
                                                            const RelocalizationAnswer& answer,
                                                            const std::string& how) {
  const PlanarTransform previous = map_from_odom_;
  map_from_odom_ = answer.map_from_odom;
  trusted_ = true;
  ++recoveries_;
  phase_ = Phase::kTracking;
  last_ended_ = now;
  ForgetObjects();
  std::vector<RelocalizationAction> actions;
  RelocalizationAction correct;
  correct.kind = RelocalizationAction::Kind::kCorrect;
  correct.map_from_odom = map_from_odom_;
  correct.message = absl::StrFormat(
      "relocalized (%s): map_from_odom moved by %.2f m, %.1f deg (%d inliers, rms %.2f m)%s",
      trigger_, (map_from_odom_.translation - previous.translation).head<2>().norm(),
      Wrap(map_from_odom_.yaw - previous.yaw) * 180.0 / M_PI, answer.inliers, answer.rms_residual_m,
      how.empty() ? "" : "; " + how);
  actions.push_back(correct);
  if (paused_task_) {
    RelocalizationAction resume;
    resume.kind = RelocalizationAction::Kind::kResumeTask;
    resume.message = "relocalized: task resumes";
    actions.push_back(resume);
    paused_task_ = false;
  }
  return actions;
}

std::vector<RelocalizationAction> RelocalizationLoop::AttemptFailed(double now,
                                                                    const std::string& why,
                                                                    const SceneGraph& graph) {
  if (attempt_ < config_.max_attempts) {
    phase_ = Phase::kTracking;  // LookAround from here starts a new look-around
    // A new look-around: its baseline is the graph of now (an answer's failure has no graph:
    // the old baseline stays, so objects seen in the first turn still count).
    std::map<int64_t, int> keep = baseline_;
    std::vector<RelocalizationAction> actions = LookAround(now, graph);
    if (graph.objects.empty()) baseline_ = std::move(keep);
    return actions;
  }
  phase_ = Phase::kTracking;
  trusted_ = false;
  ++failures_;
  last_ended_ = now;
  ForgetObjects();
  std::vector<RelocalizationAction> actions;
  RelocalizationAction hold;
  hold.kind = RelocalizationAction::Kind::kCommand;
  hold.command.kind = CommandKind::kStop;
  hold.command.id = next_command_id_++;
  hold.command.reason = "relocalization failed: the pose is not trusted";
  actions.push_back(hold);
  RelocalizationAction fail;
  fail.kind = RelocalizationAction::Kind::kFailTask;
  fail.message =
      absl::StrFormat("relocalization failed after %d attempts (%s): %s", attempt_, trigger_, why);
  actions.push_back(fail);
  paused_task_ = false;
  return actions;
}

}  // namespace semnav::reasoning
