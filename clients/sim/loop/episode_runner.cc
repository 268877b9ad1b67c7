#include "clients/sim/loop/episode_runner.h"

#include <chrono>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/sim/core/class_embedding.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/command_executor.h"
#include "clients/sim/loop/frame_encoder.h"
#include "clients/sim/loop/frame_stream.h"
#include "clients/sim/loop/instruction.h"
#include "clients/sim/loop/kidnap.h"
#include "clients/sim/loop/local_planner.h"
#include "clients/sim/loop/localization_model.h"
#include "clients/sim/loop/robot_messages.h"
#include "clients/sim/loop/robot_session.h"
#include "clients/sim/loop/shortest_path.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/common/status/grpc_status.h"

namespace semnav::sim::loop {
namespace {

namespace api = semnav::reasoning::v1;

// Lock step (docs/simulation.md, "Time"): the robot does not step before the gateway's StepDone
// for its last state. This bounds a gateway that hangs; reaching it fails the episode (and the
// bench) rather than letting the simulation run on without its commands.
constexpr absl::Duration kStepDoneTimeout = absl::Seconds(120);
// The kidnap destination's random stream, apart from the robot's (SimRobot mixes small numbers).
constexpr uint64_t kKidnapStream = 0x6b69646e6170;  // "kidnap"

bool Terminal(api::TaskStatus status) {
  return status == api::TASK_STATUS_SUCCEEDED || status == api::TASK_STATUS_FAILED ||
         status == api::TASK_STATUS_CANCELLED;
}

absl::StatusOr<api::TaskSnapshot> GetTask(api::OperatorService::Stub& op,
                                          const std::string& task_id) {
  api::GetTaskRequest request;
  request.set_task_id(task_id);
  api::GetTaskResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
  const grpc::Status status = op.GetTask(&context, request, &response);
  if (!status.ok())
    return absl::UnavailableError(absl::StrCat("GetTask: ", status.error_message()));
  return response.task();
}

absl::StatusOr<api::TaskSnapshot> Submit(api::OperatorService::Stub& op, const EpisodeSpec& spec) {
  api::SubmitInstructionRequest request;
  request.set_request_id(absl::StrCat(spec.robot_id, "-", spec.world.name, "-", spec.start_index,
                                      "-", spec.target, "-", spec.seed, "-",
                                      std::chrono::steady_clock::now().time_since_epoch().count()));
  request.set_robot_id(spec.robot_id);
  request.set_instruction(SearchInstruction(spec.target));
  request.set_exploration_strategy(RequestedStrategy(spec.strategy));
  *request.mutable_search_area() = SearchAreaOf(spec.world);
  api::SubmitInstructionResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(30));
  const grpc::Status status = op.SubmitInstruction(&context, request, &response);
  if (!status.ok()) return FromGrpcStatus(status);
  return response.task();
}

// An episode that ran out of budget leaves its task running: the operator calls it off, so the
// robot's next session does not resume it. A task that ended meanwhile is FAILED_PRECONDITION.
absl::Status CancelUnfinished(api::OperatorService::Stub& op, const std::string& task_id) {
  api::CancelTaskRequest request;
  request.set_request_id(absl::StrCat("cancel-", task_id));
  request.set_task_id(task_id);
  request.set_reason("episode budget spent");
  api::CancelTaskResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
  const absl::Status status = FromGrpcStatus(op.CancelTask(&context, request, &response));
  return absl::IsFailedPrecondition(status) ? absl::OkStatus() : status;
}

// Every episode starts from an empty map: earlier episodes' objects must not leak into this one.
absl::Status ResetMap(const std::shared_ptr<grpc::Channel>& mapping, const EpisodeSpec& spec) {
  auto stub = semnav::mapping::v1::MappingService::NewStub(mapping);
  semnav::mapping::v1::ResetMapRequest request;
  request.set_request_id(absl::StrCat("reset-", spec.robot_id, "-",
                                      std::chrono::steady_clock::now().time_since_epoch().count()));
  semnav::mapping::v1::ResetMapResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
  const grpc::Status status = stub->ResetMap(&context, request, &response);
  if (!status.ok())
    return absl::UnavailableError(absl::StrCat("ResetMap: ", status.error_message()));
  return absl::OkStatus();
}

// "oracle" landmarks: the world's objects as the robot's landmark map (map id = robot id), in the
// map frame (the world frame: odometry starts at the true start pose), with the descriptor the
// simulated detector gives each class. Stands in for mapping filling the map from its scene graph.
absl::Status UpsertOracleLandmarks(const std::shared_ptr<grpc::Channel>& relocalization,
                                   const EpisodeSpec& spec) {
  namespace reloc = semnav::relocalization::v1;
  auto stub = reloc::RelocalizationService::NewStub(relocalization);
  {
    reloc::DeleteLandmarkMapRequest request;
    request.set_map_id(spec.robot_id);
    request.set_request_id(
        absl::StrCat("delete-", spec.robot_id, "-",
                     std::chrono::steady_clock::now().time_since_epoch().count()));
    reloc::DeleteLandmarkMapResponse response;
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
    const absl::Status deleted =
        FromGrpcStatus(stub->DeleteLandmarkMap(&context, request, &response));
    if (!deleted.ok() && !absl::IsNotFound(deleted)) return deleted;
  }
  reloc::UpsertLandmarksRequest request;
  request.set_map_id(spec.robot_id);
  request.set_request_id(absl::StrCat("oracle-", spec.robot_id, "-",
                                      std::chrono::steady_clock::now().time_since_epoch().count()));
  const DetectorConfig& detector = spec.sensors.detector;
  for (const ObjectInstance& object : spec.world.objects) {
    reloc::Landmark* landmark = request.add_landmarks();
    landmark->mutable_position()->set_x(object.box.center.x());
    landmark->mutable_position()->set_y(object.box.center.y());
    landmark->mutable_position()->set_z(object.box.base_z + object.box.size.z() / 2.0);
    landmark->set_scale_m(object.box.size.maxCoeff());
    const std::vector<float> embedding =
        ClassEmbedding(object.label, detector.embedding_dim, detector.embedding_seed);
    landmark->mutable_embedding()->Assign(embedding.begin(), embedding.end());
    landmark->set_observations(1);
  }
  reloc::UpsertLandmarksResponse response;
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(30));
  return FromGrpcStatus(stub->UpsertLandmarks(&context, request, &response));
}

Eigen::Isometry3d ToIsometry(const Pose& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translate(pose.position);
  out.rotate(Eigen::AngleAxisd(pose.yaw, Eigen::Vector3d::UnitZ()));
  return out;
}

// The gateway answered and said no (a target it cannot parse, a robot it does not know): the
// episode is a failure to score, not a broken benchmark. Transport errors still stop the run.
bool Refused(const absl::Status& status) {
  return absl::IsInvalidArgument(status) || absl::IsFailedPrecondition(status) ||
         absl::IsNotFound(status);
}

std::string Stamp(const SimRobot& robot) { return absl::StrFormat("t=%.1fs ", robot.time_s()); }

void RecordTask(const api::TaskSnapshot& task, const SimRobot& robot, EpisodeResult& result) {
  RecordTaskChange(result.trace, robot.time_s(), task);
  const std::string line =
      absl::StrCat(api::TaskStatus_Name(task.status()), " ", task.phase(), ": ", task.reason(),
                   " (replans ", task.replans(), ", explore goals ", task.explore_goals(), ")");
  if (result.timeline.empty() || !absl::EndsWith(result.timeline.back(), line)) {
    result.timeline.push_back(Stamp(robot) + line);
  }
  result.final_status = task.status();
  result.final_reason = task.reason();
  result.phase = task.phase();
  result.record.model_calls =
      task.model_calls();  // every proxy call: slow path, vision, region scores
  const bool resolved =
      task.has_target() && task.target().path() != api::RESOLUTION_PATH_UNSPECIFIED;
  result.record.goals_resolved = resolved ? 1 : 0;
  result.record.goals_fast_path =
      resolved && task.target().path() == api::RESOLUTION_PATH_FAST ? 1 : 0;
}

std::string Describe(const api::RobotCommand& command) {
  switch (command.action_case()) {
    case api::RobotCommand::kNavigate: {
      const auto& goal = command.navigate().goal();
      return absl::StrFormat("navigate to (%.2f, %.2f) along %d waypoints", goal.x(), goal.y(),
                             command.navigate().path_size());
    }
    case api::RobotCommand::kRotate:
      return absl::StrFormat("rotate %.2f rad/s", command.rotate().angular_speed_rps());
    case api::RobotCommand::kHold:
      return "hold";
    case api::RobotCommand::kStop:
      return command.stop().emergency() ? "emergency stop" : "stop";
    default:
      return "command without an action";
  }
}

// Executes the gateway's commands and answers each with its feedback. Navigate goals are in the
// robot's odometry frame: `truth_from_odom` (set when odometry and truth differ) moves them into
// the world the simulator drives in.
absl::Status ExecuteCommands(RobotSession& session, CommandExecutor& executor,
                             const SimRobot& robot, const std::vector<api::RobotCommand>& commands,
                             EpisodeResult& result,
                             const std::optional<Pose>& truth_from_odom = std::nullopt) {
  for (const api::RobotCommand& sent : commands) {
    api::RobotCommand command = sent;
    if (truth_from_odom.has_value()) ToTruthFrame(command, *truth_from_odom);
    const Feedback feedback = executor.Start(command);
    RecordFeedback(result.trace, robot.time_s(), feedback.kind, feedback.detail);
    result.timeline.push_back(
        absl::StrCat(Stamp(robot), "command ", command.command_id(), ": ", Describe(command),
                     " -> ", api::FeedbackKind_Name(feedback.kind), " ", feedback.detail));
    if (command.action_case() == api::RobotCommand::kNavigate) {
      result.goals.emplace_back(command.navigate().goal().x(), command.navigate().goal().y());
      RecordNavigateGoal(result.trace, robot.time_s(), result.goals.back());
    }
    if (absl::Status s = session.Send(FeedbackMessage(feedback)); !s.ok()) return s;
  }
  return absl::OkStatus();
}

}  // namespace

api::ExplorationStrategy RequestedStrategy(const std::string& label) {
  api::ExplorationStrategy strategy = api::EXPLORATION_STRATEGY_UNSPECIFIED;
  if (!api::ExplorationStrategy_Parse(absl::StrCat("EXPLORATION_STRATEGY_", label), &strategy)) {
    return api::EXPLORATION_STRATEGY_UNSPECIFIED;
  }
  return strategy;
}

absl::StatusOr<EpisodeResult> RunEpisode(const EpisodeSpec& spec, const Endpoints& endpoints,
                                         const StepObserver& observer) {
  if (spec.start_index < 0 || spec.start_index >= static_cast<int>(spec.world.starts.size())) {
    return absl::InvalidArgumentError(
        absl::StrCat("start_index ", spec.start_index, " not in world ", spec.world.name));
  }
  const std::string label = spec.target_label.empty() ? spec.target : spec.target_label;
  const StartPose& start = spec.world.starts[spec.start_index];
  const Scene scene = Scene::Build(spec.world);
  RobotConfig robot_config = RobotConfig::ForModality(start.modality);
  if (start.modality == Modality::kGround) robot_config.camera_pitch = spec.ground_camera_pitch;
  SensorConfig sensors = spec.sensors;
  sensors.rgb = sensors.rgb || spec.camera_frames;
  SimRobot robot(spec.world, scene, start, robot_config, sensors, spec.seed);
  // The true map the robot's body meets, and the target's success region on it (scoring, l_i).
  const GroundTruthGrid grid =
      RasterizeOccupancy(spec.world, BodyRaster(robot_config, start.position.z()));
  const SuccessRegion region = SuccessRegion::Build(spec.world, label, grid, spec.success_radius);
  CommandExecutor executor(robot, LiveMapPlanner(endpoints.planning, robot_config.radius));

  if (absl::Status s = ResetMap(endpoints.mapping, spec); !s.ok()) return s;
  if (spec.landmarks == "oracle") {
    if (endpoints.relocalization == nullptr)
      return absl::InvalidArgumentError("oracle landmarks need relocalization");
    if (absl::Status s = UpsertOracleLandmarks(endpoints.relocalization, spec); !s.ok()) return s;
  }
  // Losing the pose: what the robot believes is the gateway's correction applied to its odometry.
  SimLocalizer localizer(spec.localizer);
  RecoveryTracker recovery;
  Pose map_from_odom;
  bool kidnapped = false;
  const bool frames_differ = spec.sensors.odometry.enabled || spec.kidnap.has_value();
  auto believed = [&]() { return Compose(map_from_odom, robot.odometry_pose()); };
  // The robot distrusts its pose while its localizer reports LOST/UNCERTAIN or the gateway
  // relocalizes it; its frames then say so (SensorFrame.pose_untrusted), so mapping keeps what they
  // show out of the landmark maps.
  api::LocalizationStatus reported = api::LOCALIZATION_STATUS_UNSPECIFIED;
  bool gateway_relocalizing = false;
  api::SessionHello hello = Hello(spec.robot_id, start.modality, robot_config);
  hello.set_clock(api::CLOCK_KIND_SIMULATED);
  absl::StatusOr<std::unique_ptr<RobotSession>> session =
      RobotSession::Open(endpoints.gateway, hello);
  if (!session.ok()) return session.status();
  FrameStream frames(endpoints.mapping);
  auto op = api::OperatorService::NewStub(endpoints.gateway);

  EpisodeResult result;
  result.record.strategy = spec.strategy;
  result.record.world = spec.world.name;
  result.record.target = spec.target;
  result.record.group = spec.report_group.empty() ? ReportGroup(start.modality) : spec.report_group;
  // One capture per step: depth and detections to mapping (acknowledged), the colour image to
  // the gateway when asked for.
  uint64_t mapping_revision = 0;  // of the last acknowledged frame
  auto send_frame = [&]() -> absl::Status {
    SensorFrame captured = robot.Capture();
    if (!IsIdentity(map_from_odom)) {  // the robot maps where it believes it is
      captured.odometry_pose = believed();
      captured.odom_from_camera = ToIsometry(map_from_odom) * captured.odom_from_camera;
    }
    for (const Detection& d : captured.detections.detections) {
      if (d.object_index >= 0) result.seen_objects.insert(d.object_index);
      RecordDetection(result.trace, robot.time_s(), spec.world, label, d.object_index);
    }
    semnav::mapping::v1::SensorFrame encoded = EncodeFrame(captured, spec.robot_id);
    encoded.set_pose_untrusted(reported == api::LOCALIZATION_STATUS_LOST ||
                               reported == api::LOCALIZATION_STATUS_UNCERTAIN ||
                               gateway_relocalizing);
    absl::StatusOr<semnav::mapping::v1::FrameAck> ack = frames.Send(encoded);
    if (!ack.ok()) return ack.status();
    mapping_revision = ack->revision();
    if (!spec.camera_frames) return absl::OkStatus();
    if (spec.on_camera_frame) spec.on_camera_frame(captured);
    absl::StatusOr<api::ConnectRequest> camera = EncodeCameraFrame(captured);
    return camera.ok() ? (*session)->Send(*camera) : camera.status();
  };
  // One lock step: the state (after the step's frame and feedback), the gateway's StepDone, and
  // the commands it sent before it, executed at once.
  uint64_t step_number = 0;
  auto exchange = [&]() -> absl::Status {
    ++step_number;
    api::ConnectRequest state =
        StepStateMessage(robot, spec.robot_id, step_number, mapping_revision);
    const api::LocalizationStatus status =
        localizer.Update(robot.time_s(), believed(), robot.pose(), !gateway_relocalizing);
    state.mutable_state()->set_localization(status);
    reported = status;
    recovery.OnReport(robot.time_s(), status);
    if (absl::Status s = (*session)->Send(state); !s.ok()) return s;
    absl::StatusOr<std::vector<api::RobotCommand>> commands =
        (*session)->TakeStepCommands(step_number, kStepDoneTimeout);
    if (!commands.ok()) return commands.status();
    if (std::optional<api::LocalizationUpdate> update = (*session)->TakeLocalization()) {
      gateway_relocalizing = update->relocalizing();
      const Pose corrected = FromProto(update->map_from_odom());
      const bool changed = (corrected.position - map_from_odom.position).norm() > 1e-9 ||
                           std::abs(corrected.yaw - map_from_odom.yaw) > 1e-12;
      map_from_odom = corrected;
      if (changed) {
        recovery.OnCorrection(robot.time_s(), believed(),
                              localizer.Expected(believed(), robot.pose()));
        result.timeline.push_back(absl::StrCat(
            Stamp(robot),
            absl::StrFormat(
                "gateway correction map_from_odom (%.2f, %.2f, %.1f deg); believed pose off "
                "by %.2f m",
                corrected.position.x(), corrected.position.y(), corrected.yaw * 180.0 / M_PI,
                (believed().position - robot.pose().position).head<2>().norm())));
      }
    }
    std::optional<Pose> truth_from_odom;
    if (frames_differ) truth_from_odom = Compose(robot.pose(), Inverse(robot.odometry_pose()));
    return ExecuteCommands(**session, executor, robot, *commands, result, truth_from_odom);
  };
  // The gateway must know where the robot is and what it sees before it plans.
  if (absl::Status s = send_frame(); !s.ok()) return s;
  if (absl::Status s = exchange(); !s.ok()) return s;
  absl::StatusOr<api::TaskSnapshot> task = Submit(*op, spec);
  if (!task.ok() && !Refused(task.status())) {
    return absl::UnavailableError(absl::StrCat("SubmitInstruction: ", task.status().message()));
  }
  if (task.ok()) {
    result.task_id = task->task_id();
    RecordTask(*task, robot, result);
  } else {
    result.final_status = api::TASK_STATUS_FAILED;
    result.final_reason = absl::StrCat("instruction refused: ", task.status().ToString());
    result.trace.instruction_refused = true;
    result.timeline.push_back(Stamp(robot) + result.final_reason);
  }

  // Step `step` starts with the gateway's answer to the state that ended the last one (or, first,
  // to the submission); after the budget's last step that answer still counts.
  for (int step = 0; task.ok(); ++step) {
    if (absl::Status s = exchange(); !s.ok()) return s;
    task = GetTask(*op, result.task_id);
    if (!task.ok()) return task.status();
    RecordTask(*task, robot, result);
    // The agent's stop action ends the episode; a task that ended without one ends it too.
    if (executor.stop_issued() || Terminal(result.final_status) || step == spec.max_steps) break;
    if (spec.kidnap.has_value() && !kidnapped && robot.time_s() >= spec.kidnap->at_s) {
      kidnapped = true;
      std::vector<Eigen::Vector2d> went = result.trajectory;
      went.push_back(start.position.head<2>());
      Rng rng(MixSeed(spec.seed, kKidnapStream));
      const std::optional<Pose> to = KidnapDestination(grid, robot.pose(), went, *spec.kidnap, rng);
      if (!to.has_value()) {
        result.timeline.push_back(
            absl::StrCat(Stamp(robot), "not kidnapped: no free cell on its way qualifies"));
      } else {
        robot.Kidnap(*to);
        executor.Interrupt();
        recovery.OnKidnap(robot.time_s());
        const Pose odom = believed();
        result.timeline.push_back(absl::StrCat(
            Stamp(robot),
            absl::StrFormat("kidnapped to (%.2f, %.2f, %.0f deg); the robot believes (%.2f, "
                            "%.2f, %.0f deg)",
                            to->position.x(), to->position.y(), to->yaw * 180.0 / M_PI,
                            odom.position.x(), odom.position.y(), odom.yaw * 180.0 / M_PI)));
      }
    }
    const std::optional<Feedback> outcome = executor.Step(spec.step_s);
    result.steps = step + 1;
    result.trajectory.push_back(robot.pose().position.head<2>());
    RecordSample(result.trace, robot.time_s(), result.trajectory.back(), spec.world, label, region);
    if (outcome.has_value()) {
      result.timeline.push_back(absl::StrCat(
          Stamp(robot), "robot: ", api::FeedbackKind_Name(outcome->kind), " ", outcome->detail,
          absl::StrFormat(" at (%.2f, %.2f)", robot.pose().position.x(),
                          robot.pose().position.y())));
      RecordFeedback(result.trace, robot.time_s(), outcome->kind, outcome->detail);
      if (absl::Status s = (*session)->Send(FeedbackMessage(*outcome)); !s.ok()) return s;
    }
    if (absl::Status s = send_frame(); !s.ok()) return s;
    if (observer) observer(step, result);
  }

  if (task.ok() && !Terminal(result.final_status)) {
    if (absl::Status s = CancelUnfinished(*op, result.task_id); !s.ok()) return s;
    result.timeline.push_back(Stamp(robot) + "budget spent: task cancelled");
    result.trace.budget_spent = true;
  }

  // The stop action is the agent declaring it has arrived: the STOP a task sends when it gives
  // up (FAILED) halts the robot but declares nothing, even if it happens near a target.
  const bool declared = executor.stop_issued() && result.final_status == api::TASK_STATUS_SUCCEEDED;
  const StopOutcome outcome =
      ScoreStop(spec.world, region, label, robot.pose().position.head<2>(), declared);
  result.stop_issued = declared;
  result.collisions = static_cast<int>(robot.collisions().size());
  result.record.success = outcome.success;
  result.record.distance_to_goal_m = outcome.distance_to_goal_m;
  result.record.path_m = robot.path_length_m();
  result.record.time_s = robot.time_s();
  result.record.energy_j = robot.energy_j();
  // l_i on the true map the robot's body meets (a fly-roll robot's l_i is its rolling path, an
  // upper bound).
  auto planning = semnav::planning::v1::PlanningService::NewStub(endpoints.planning);
  absl::StatusOr<double> shortest =
      ShortestPathToTarget(*planning, region, grid, start.position.head<2>());
  if (!shortest.ok() && !absl::IsNotFound(shortest.status())) return shortest.status();
  result.record.shortest_path_m = shortest.ok() ? *shortest : 0.0;  // unreachable: SPL term is 0
  result.trace.stop_declared = declared;
  result.trace.success = outcome.success;
  result.trace.end_s = robot.time_s();
  result.trace.bounds_min = spec.world.bounds_min;
  result.trace.bounds_max = spec.world.bounds_max;
  result.record.failure_cause = FailureCauseName(ClassifyFailure(result.trace, spec.taxonomy));
  result.record.start_index = spec.start_index;
  result.record.losses = recovery.losses();
  result.record.recovery_times_s = recovery.times_s();
  result.record.recovery_errors_m = recovery.errors_m();
  result.record.recovery_errors_deg = recovery.errors_deg();
  result.record.final_pose_error_m = (believed().position - robot.pose().position).head<2>().norm();
  return result;
}

}  // namespace semnav::sim::loop
