#include "clients/sim/loop/two_robot_scenario.h"

#include <grpcpp/grpcpp.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "clients/sim/core/camera_model.h"
#include "clients/sim/core/detector.h"
#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/nearest_goal_search.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/frame_encoder.h"
#include "clients/sim/loop/frame_stream.h"
#include "clients/sim/loop/stop_on_sight.h"
#include "clients/sim/worlds/indoor_generator.h"
#include "clients/sim/worlds/start_poses.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"

namespace semnav::sim::loop {
namespace {

namespace mv1 = semnav::mapping::v1;
namespace rv1 = semnav::relocalization::v1;

constexpr int kStableDetections = 3;      // mapping.landmarks.min_detections default
constexpr double kSecondsPerFrame = 0.5;  // simulated stamp between captures
constexpr double kTargetMatchM = 0.5;  // an instance within this of a true footprint is that object
constexpr absl::Duration kPublishWait = absl::Seconds(20);

grpc::Status Call(const std::function<grpc::Status(grpc::ClientContext*)>& call,
                  int deadline_s = 30) {
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(deadline_s));
  return call(&context);
}

absl::Status FromGrpc(const grpc::Status& status, absl::string_view what) {
  if (status.ok()) return absl::OkStatus();
  return absl::Status(static_cast<absl::StatusCode>(status.error_code()),
                      absl::StrCat(what, ": ", status.error_message()));
}

Eigen::Isometry3d FromProto(const semnav::common::v1::Pose& pose) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.translation() =
      Eigen::Vector3d(pose.position().x(), pose.position().y(), pose.position().z());
  out.linear() = Eigen::Quaterniond(pose.orientation().w(), pose.orientation().x(),
                                    pose.orientation().y(), pose.orientation().z())
                     .normalized()
                     .toRotationMatrix();
  return out;
}

Eigen::Isometry3d PlanarTransform(double yaw, const Eigen::Vector2d& shift) {
  Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
  out.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  out.translation() = Eigen::Vector3d(shift.x(), shift.y(), 0.0);
  return out;
}

double YawOf(const Eigen::Isometry3d& pose) {
  return std::atan2(pose.linear()(1, 0), pose.linear()(0, 0));
}

absl::Status ResetMap(const std::shared_ptr<grpc::Channel>& mapping,
                      const std::string& request_id) {
  auto stub = mv1::MappingService::NewStub(mapping);
  mv1::ResetMapRequest request;
  request.set_request_id(request_id);
  mv1::ResetMapResponse response;
  return FromGrpc(
      Call([&](grpc::ClientContext* c) { return stub->ResetMap(c, request, &response); }),
      "ResetMap");
}

absl::Status SaveMap(const std::shared_ptr<grpc::Channel>& mapping, const std::string& map_id) {
  auto stub = mv1::MappingService::NewStub(mapping);
  mv1::SaveMapRequest request;
  request.set_request_id(absl::StrCat("save-", map_id));
  request.set_map_id(map_id);
  mv1::SaveMapResponse response;
  return FromGrpc(
      Call([&](grpc::ClientContext* c) { return stub->SaveMap(c, request, &response); }),
      "SaveMap");
}

absl::StatusOr<std::vector<mv1::SceneObject>> StableObjects(
    const std::shared_ptr<grpc::Channel>& mapping) {
  auto stub = mv1::MappingService::NewStub(mapping);
  mv1::GetSceneGraphRequest request;
  mv1::GetSceneGraphResponse response;
  if (absl::Status s = FromGrpc(
          Call([&](grpc::ClientContext* c) { return stub->GetSceneGraph(c, request, &response); }),
          "GetSceneGraph");
      !s.ok()) {
    return s;
  }
  std::vector<mv1::SceneObject> out;
  for (const mv1::SceneObject& o : response.graph().objects()) {
    if (static_cast<int>(o.observation_count()) >= kStableDetections) out.push_back(o);
  }
  return out;
}

// Landmarks in relocalization's map `map_id` once mapping's background push made it.
absl::StatusOr<int> AwaitLandmarkMap(const std::shared_ptr<grpc::Channel>& relocalization,
                                     const std::string& map_id) {
  auto stub = rv1::RelocalizationService::NewStub(relocalization);
  const absl::Time give_up = absl::Now() + kPublishWait;
  while (true) {
    rv1::GetLandmarkMapRequest request;
    request.set_map_id(map_id);
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
    auto reader = stub->GetLandmarkMap(&context, request);
    rv1::GetLandmarkMapResponse page;
    int total = -1;
    while (reader->Read(&page)) total = static_cast<int>(page.total_landmarks());
    const grpc::Status status = reader->Finish();
    if (status.ok() && total >= 0) return total;
    if (!status.ok() && status.error_code() != grpc::StatusCode::NOT_FOUND) {
      return FromGrpc(status, absl::StrCat("GetLandmarkMap ", map_id));
    }
    if (absl::Now() > give_up) {
      return absl::DeadlineExceededError(
          absl::StrCat("landmark map ", map_id, " never reached relocalization"));
    }
    absl::SleepFor(absl::Milliseconds(100));
  }
}

// Turns a fresh robot in place at `at`, one capture per heading step, streamed to mapping with
// its camera pose expressed in the robot's odometry frame (`odom_from_world`).
absl::StatusOr<int> LookAround(const World& world, const Scene& scene, const Eigen::Vector2d& at,
                               double start_yaw, uint64_t seed, double step_deg,
                               const Eigen::Isometry3d& odom_from_world,
                               const std::string& robot_id, FrameStream& frames, double& clock_s,
                               FrameStream* lost_in_a = nullptr, const std::string& lost_id = "") {
  const RobotConfig robot_config = RobotConfig::ForModality(Modality::kGround);
  StartPose start;
  start.position = Eigen::Vector3d(at.x(), at.y(), 0.0);
  start.yaw = start_yaw;
  SimRobot robot(world, scene, start, robot_config, SensorConfig{}, seed);
  const int steps = std::max(1, static_cast<int>(std::lround(360.0 / step_deg)));
  for (int k = 0; k < steps; ++k) {
    if (k > 0) {
      if (absl::Status s = robot.Apply(Rotate{WrapAngle(start_yaw + k * step_deg * M_PI / 180.0)});
          !s.ok())
        return s;
      for (int i = 0; i < 400 && robot.Step(0.05).activity == RobotActivity::kTurning; ++i) {
      }
    }
    SensorFrame frame = robot.Capture();
    frame.time_s = clock_s;
    clock_s += kSecondsPerFrame;
    frame.odom_from_camera = odom_from_world * frame.odom_from_camera;
    mv1::SensorFrame encoded = EncodeFrame(frame, robot_id);
    absl::StatusOr<mv1::FrameAck> ack = frames.Send(encoded);
    if (!ack.ok()) return ack.status();
    if (lost_in_a != nullptr) {
      // The same depth to A's mapping as a robot lost in A's map: it stays out of A's grid and
      // becomes the scan MatchLostScan matches. Its detections stay home (they are in B's frame).
      encoded.clear_detections();
      encoded.set_detector_ran(false);
      encoded.set_pose_untrusted(true);
      encoded.mutable_header()->set_robot_id(lost_id);
      absl::StatusOr<mv1::FrameAck> lost_ack = lost_in_a->Send(encoded);
      if (!lost_ack.ok()) return lost_ack.status();
    }
  }
  return steps;
}

// The free cell of the largest free region inside `room` nearest its vertex centroid.
std::optional<Eigen::Vector2d> RoomViewpoint(const Room& room, const GroundTruthGrid& grid,
                                             const std::vector<uint8_t>& region) {
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& v : room.polygon) centroid += v;
  centroid /= std::max<size_t>(1, room.polygon.size());
  std::optional<Eigen::Vector2d> best;
  double best_d = 1e18;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (region[static_cast<size_t>(y) * grid.width + x] == 0) continue;
      const Eigen::Vector2d p = grid.CellCentre(x, y);
      const double d = (p - centroid).squaredNorm();
      if (d < best_d && PointInPolygon(room.polygon, p)) {
        best_d = d;
        best = p;
      }
    }
  }
  return best;
}

const Room* RoomAt(const World& world, const Eigen::Vector2d& p) {
  for (const Room& room : world.rooms) {
    if (PointInPolygon(room.polygon, p)) return &room;
  }
  return nullptr;
}

// A stable instance of A's map and the world object it is.
struct Target {
  mv1::SceneObject instance;
  const ObjectInstance* object = nullptr;
};

std::vector<Target> MatchTargets(const World& world,
                                 const std::vector<mv1::SceneObject>& instances) {
  std::vector<Target> out;
  for (const mv1::SceneObject& instance : instances) {
    const Eigen::Vector2d p(instance.position().x(), instance.position().y());
    const ObjectInstance* best = nullptr;
    double best_d = kTargetMatchM;
    for (const ObjectInstance& object : world.objects) {
      if (object.label != instance.label()) continue;
      const double d = DistanceToBoxFootprint(object.box, p);
      if (d <= best_d) {
        best_d = d;
        best = &object;
      }
    }
    if (best != nullptr) out.push_back({instance, best});
  }
  return out;
}

// B's scan of its look-arounds against A's grid (MatchLostScan): around `coarse` (a_from_b), or
// globally without one. The refined a_from_b, or nullopt when mapping has no good answer.
absl::StatusOr<std::optional<Eigen::Isometry3d>> MatchInA(
    mv1::MappingService::Stub& mapping_a, const std::string& robot_id,
    const std::optional<Eigen::Isometry3d>& coarse) {
  mv1::MatchLostScanRequest request;
  request.set_robot_id(robot_id);
  if (coarse.has_value()) {
    request.mutable_coarse()->set_x(coarse->translation().x());
    request.mutable_coarse()->set_y(coarse->translation().y());
    request.mutable_coarse()->set_yaw(YawOf(*coarse));
  } else {
    request.set_global(true);
  }
  mv1::MatchLostScanResponse response;
  const grpc::Status status =
      Call([&](grpc::ClientContext* c) { return mapping_a.MatchLostScan(c, request, &response); });
  if (status.error_code() == grpc::StatusCode::NOT_FOUND ||
      status.error_code() == grpc::StatusCode::FAILED_PRECONDITION) {
    return std::optional<Eigen::Isometry3d>();
  }
  if (!status.ok()) return FromGrpc(status, "MatchLostScan");
  if (!response.refined()) return std::optional<Eigen::Isometry3d>();
  return std::optional<Eigen::Isometry3d>(
      PlanarTransform(response.correction().yaw(),
                      Eigen::Vector2d(response.correction().x(), response.correction().y())));
}

}  // namespace

absl::StatusOr<TwoRobotWorldResult> RunTwoRobotWorld(const TwoRobotOptions& options,
                                                     const TwoRobotEndpoints& endpoints) {
  if (options.trials < 1 || options.trials > 1000)
    return absl::InvalidArgumentError("trials must be in [1, 1000]");
  if (!(options.success_radius_m > 0.0 && options.approach_margin_m >= 0.0 &&
        options.approach_margin_m < options.success_radius_m)) {
    return absl::InvalidArgumentError("need 0 <= approach_margin_m < success_radius_m");
  }
  if (!(options.look_step_deg >= 5.0 && options.look_step_deg <= 90.0 &&
        options.survey_step_deg >= 5.0 && options.survey_step_deg <= 90.0)) {
    return absl::InvalidArgumentError("look_step_deg and survey_step_deg must be in [5, 90]");
  }
  if (!(options.max_offset_m >= 0.0 && options.max_offset_m <= 1000.0)) {
    return absl::InvalidArgumentError("max_offset_m must be in [0, 1000]");
  }
  if (options.max_look_arounds < 1 || options.max_look_arounds > 10) {
    return absl::InvalidArgumentError("max_look_arounds must be in [1, 10]");
  }
  if (!(options.move_m >= 0.5 && options.move_m <= 20.0))
    return absl::InvalidArgumentError("move_m must be in [0.5, 20]");
  TwoRobotWorldResult result;
  result.world = absl::StrCat("two_robots_home_", options.world_seed);
  World world = GenerateIndoor(result.world, IndoorOptions{}, options.world_seed);
  RemoveUnreachableObjects(world, Modality::kGround, 0.0, options.success_radius_m);
  const Scene scene = Scene::Build(world);
  const GroundTruthGrid grid = ModalityGrid(world, Modality::kGround, 0.0);
  const std::vector<uint8_t> region = LargestFreeRegion(grid);

  // Robot A: a look-around in every room; its odometry frame is the world frame.
  if (absl::Status s = ResetMap(endpoints.mapping_a, absl::StrCat("reset-a-", options.world_seed));
      !s.ok())
    return s;
  double clock_s = 0.0;
  {
    FrameStream frames(endpoints.mapping_a);
    for (size_t i = 0; i < world.rooms.size(); ++i) {
      const std::optional<Eigen::Vector2d> at = RoomViewpoint(world.rooms[i], grid, region);
      if (!at) continue;
      absl::StatusOr<int> sent = LookAround(world, scene, *at, 0.0, MixSeed(options.world_seed, i),
                                            options.survey_step_deg, Eigen::Isometry3d::Identity(),
                                            "robot_a", frames, clock_s);
      if (!sent.ok()) return sent.status();
      ++result.a_viewpoints;
      result.a_frames += *sent;
    }
  }
  const std::string map_a = absl::StrCat("two_robots_a_", options.world_seed);
  if (absl::Status s = SaveMap(endpoints.mapping_a, map_a); !s.ok()) return s;
  absl::StatusOr<int> a_landmarks = AwaitLandmarkMap(endpoints.relocalization, map_a);
  if (!a_landmarks.ok()) return a_landmarks.status();
  result.a_landmarks = *a_landmarks;
  absl::StatusOr<std::vector<mv1::SceneObject>> a_objects = StableObjects(endpoints.mapping_a);
  if (!a_objects.ok()) return a_objects.status();
  const std::vector<Target> targets = MatchTargets(world, *a_objects);

  std::vector<int> free_cells;
  for (size_t i = 0; i < region.size(); ++i) {
    if (region[i] != 0) free_cells.push_back(static_cast<int>(i));
  }
  if (free_cells.empty())
    return absl::FailedPreconditionError(absl::StrCat(result.world, " has no free cell"));
  auto relocalization = rv1::RelocalizationService::NewStub(endpoints.relocalization);
  auto mapping_a = mv1::MappingService::NewStub(endpoints.mapping_a);
  for (int t = 0; t < options.trials; ++t) {
    TwoRobotTrial trial;
    trial.index = t;
    Rng rng(MixSeed(MixSeed(options.trial_seed, options.world_seed), static_cast<uint64_t>(t)));
    const int cell =
        free_cells[static_cast<size_t>(rng.UniformInt(0, static_cast<int>(free_cells.size()) - 1))];
    const Eigen::Vector2d start = grid.CellCentre(cell % grid.width, cell / grid.width);
    const double start_yaw = rng.Uniform(-M_PI, M_PI);
    // B's odometry frame: the world turned and shifted by an offset B does not know.
    const Eigen::Isometry3d odom_b_from_world =
        PlanarTransform(rng.Uniform(-M_PI, M_PI),
                        Eigen::Vector2d(rng.Uniform(-options.max_offset_m, options.max_offset_m),
                                        rng.Uniform(-options.max_offset_m, options.max_offset_m)));
    const Eigen::Isometry3d world_from_odom_b = odom_b_from_world.inverse();
    // A target A saw, out of the room B starts in (B cannot see it from there).
    const Room* start_room = RoomAt(world, start);
    std::vector<const Target*> candidates;
    for (const Target& target : targets) {
      if (start_room == nullptr || target.object->room != start_room->name)
        candidates.push_back(&target);
    }
    if (candidates.empty()) {
      trial.failure = "no target outside B's room";
      result.trials.push_back(trial);
      continue;
    }
    const Target& target = *candidates[static_cast<size_t>(
        rng.UniformInt(0, static_cast<int>(candidates.size()) - 1))];
    trial.target_id = target.object->id;
    trial.target_label = target.object->label;

    if (absl::Status s =
            ResetMap(endpoints.mapping_b, absl::StrCat("reset-b-", options.world_seed, "-", t));
        !s.ok()) {
      return s;
    }
    // B looks around where it stands; while AlignMaps gives no reliable pose, it moves a short
    // way (move_m by path, away from where it already looked) and looks around again, adding to
    // its map. Those moves count in B's path.
    Eigen::Vector2d at = start;
    double yaw = start_yaw;
    std::vector<Eigen::Vector2d> looked;
    double moved_m = 0.0;
    Eigen::Isometry3d a_from_b = Eigen::Isometry3d::Identity();
    const std::string lost_id = absl::StrCat("robot_b_", options.world_seed, "_", t);
    // B's frame to A's, as the true transform, for the error figures.
    auto record_error = [&](const Eigen::Isometry3d& estimate) {
      const Eigen::Vector3d start_in_b =
          odom_b_from_world * Eigen::Vector3d(start.x(), start.y(), 0.0);
      trial.alignment_error_m = (estimate * start_in_b - world_from_odom_b * start_in_b).norm();
      trial.alignment_error_deg =
          std::abs(Eigen::AngleAxisd(estimate.linear() * world_from_odom_b.linear().transpose())
                       .angle()) *
          180.0 / M_PI;
    };
    for (int look = 0; look < options.max_look_arounds; ++look) {
      if (look > 0) {
        const std::optional<NearestGoal> next =
            NearestReachableGoal(grid, at, [&](const Eigen::Vector2d& p) {
              return std::all_of(looked.begin(), looked.end(), [&](const Eigen::Vector2d& q) {
                return (p - q).norm() >= options.move_m;
              });
            });
        if (!next) break;
        moved_m += next->length_m;
        yaw = std::atan2(next->goal.y() - at.y(), next->goal.x() - at.x());
        at = next->goal;
      }
      looked.push_back(at);
      trial.look_arounds = look + 1;
      {
        FrameStream frames(endpoints.mapping_b);
        std::optional<FrameStream> lost_in_a;
        if (options.scan_match) lost_in_a.emplace(endpoints.mapping_a);
        absl::StatusOr<int> sent =
            LookAround(world, scene, at, yaw, rng.Next(), options.look_step_deg, odom_b_from_world,
                       "robot_b", frames, clock_s, lost_in_a ? &*lost_in_a : nullptr, lost_id);
        if (!sent.ok()) return sent.status();
      }
      // AlignMaps of B's map so far to A's: why it gave B no pose to move on ("" = it did).
      auto align_by_objects = [&]() -> absl::StatusOr<std::string> {
        absl::StatusOr<std::vector<mv1::SceneObject>> b_objects =
            StableObjects(endpoints.mapping_b);
        if (!b_objects.ok()) return b_objects.status();
        if (b_objects->empty()) return std::string("B saw no stable object");
        const std::string map_b =
            absl::StrCat("two_robots_b_", options.world_seed, "_", t, "_", look);
        if (absl::Status s = SaveMap(endpoints.mapping_b, map_b); !s.ok()) return s;
        absl::StatusOr<int> b_landmarks = AwaitLandmarkMap(endpoints.relocalization, map_b);
        if (!b_landmarks.ok()) return b_landmarks.status();
        trial.b_landmarks = *b_landmarks;
        rv1::AlignMapsRequest align;
        align.set_reference_map_id(map_a);
        align.set_moving_map_id(map_b);
        rv1::AlignMapsResponse aligned;
        const absl::Time sent_at = absl::Now();
        const grpc::Status status = Call(
            [&](grpc::ClientContext* c) { return relocalization->AlignMaps(c, align, &aligned); });
        trial.align_ms = absl::ToDoubleMilliseconds(absl::Now() - sent_at);
        if (!status.ok()) {
          if (status.error_code() != grpc::StatusCode::NOT_FOUND)
            return FromGrpc(status, "AlignMaps");
          return absl::StrCat("alignment failed: ", status.error_message());
        }
        trial.aligned = true;
        trial.reliable = aligned.solution().reliable();
        trial.inliers = static_cast<int>(aligned.solution().inlier_count());
        trial.rms_residual_m = aligned.solution().rms_residual_m();
        a_from_b = FromProto(aligned.solution().map_from_query());
        // A's frame is the world frame, so the true a_from_b is world_from_odom_b.
        record_error(a_from_b);
        return std::string(trial.reliable ? "" : "alignment not reliable: B does not move on it");
      };
      absl::StatusOr<std::string> why_not = align_by_objects();
      if (!why_not.ok()) return why_not.status();
      if (why_not->empty()) {
        trial.alignment = kAlignedByObjects;
        if (options.scan_match) {  // the walls refine the objects' answer
          absl::StatusOr<std::optional<Eigen::Isometry3d>> refined =
              MatchInA(*mapping_a, lost_id, a_from_b);
          if (!refined.ok()) return refined.status();
          if (refined->has_value()) {
            a_from_b = **refined;
            record_error(a_from_b);
            trial.alignment = kAlignedByObjectsScanRefined;
          }
        }
        break;
      }
      if (options.scan_match) {  // without a reliable object alignment, the walls against A's grid
        absl::StatusOr<std::optional<Eigen::Isometry3d>> found =
            MatchInA(*mapping_a, lost_id, std::nullopt);
        if (!found.ok()) return found.status();
        if (found->has_value()) {
          a_from_b = **found;
          record_error(a_from_b);
          trial.aligned = trial.reliable = true;
          trial.alignment = kAlignedByGlobalScanMatch;
          break;
        }
      }
      trial.failure = *why_not;
    }
    if (!trial.reliable) {
      result.trials.push_back(trial);
      continue;
    }
    trial.failure.clear();
    // Where B believes the target is, in the world: A's instance through B's estimate and B's true
    // frame.
    const Eigen::Isometry3d believed = world_from_odom_b * a_from_b.inverse();
    const mv1::SceneObject& instance = target.instance;
    const Eigen::Vector3d centre =
        believed *
        Eigen::Vector3d(instance.position().x(), instance.position().y(), instance.position().z());
    BoxShape believed_box;
    believed_box.center = centre.head<2>();
    believed_box.yaw = YawOf(believed);
    believed_box.size =
        Eigen::Vector3d(std::max(instance.size().x(), 0.01), std::max(instance.size().y(), 0.01),
                        std::max(instance.size().z(), 0.01));
    const double aim = options.success_radius_m - options.approach_margin_m;
    const std::optional<NearestGoal> route = NearestReachableGoal(
        grid, at,
        [&](const Eigen::Vector2d& p) { return DistanceToBoxFootprint(believed_box, p) <= aim; });
    const std::optional<NearestGoal> shortest =
        NearestReachableGoal(grid, start, [&](const Eigen::Vector2d& p) {
          return DistanceToBoxFootprint(target.object->box, p) <= options.success_radius_m;
        });
    if (!shortest) {
      trial.failure = "target unreachable from B's start";
      result.trials.push_back(trial);
      continue;
    }
    trial.shortest_m = shortest->length_m;
    if (!route) {
      trial.failure = "believed goal unreachable";
      result.trials.push_back(trial);
      continue;
    }
    const CameraIntrinsics camera;
    const size_t stop =
        StopOnSight(route->path, world, scene, *target.object,
                    RobotConfig::ForModality(Modality::kGround).camera_height,
                    std::atan(0.5 * camera.width / camera.fx), DetectorConfig{}.max_range,
                    options.success_radius_m - options.sight_margin_m);
    double driven = 0.0;
    for (size_t i = 0; i < stop; ++i) driven += (route->path[i + 1] - route->path[i]).norm();
    const Eigen::Vector2d stopped_at = route->path.empty() ? at : route->path[stop];
    trial.path_m = moved_m + driven;
    trial.look_m = moved_m;
    const std::optional<NearestGoal> straight =
        NearestReachableGoal(grid, at, [&](const Eigen::Vector2d& p) {
          return DistanceToBoxFootprint(target.object->box, p) <= options.success_radius_m;
        });
    trial.route_ratio = straight && straight->length_m > 0.0 ? driven / straight->length_m : 1.0;
    trial.path_ratio =
        trial.shortest_m > 0.0 ? trial.path_m / trial.shortest_m : (trial.path_m > 0.0 ? 1e9 : 1.0);
    trial.distance_to_target_m = DistanceToBoxFootprint(target.object->box, stopped_at);
    trial.success = trial.distance_to_target_m <= options.success_radius_m;
    if (!trial.success) trial.failure = "stopped outside the success radius";
    result.trials.push_back(trial);
  }
  return result;
}

}  // namespace semnav::sim::loop
