// What one closed-loop episode is and what it produced.
#pragma once

#include <grpcpp/channel.h>

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "clients/sim/core/episode_metrics.h"
#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/sensor_frame.h"
#include "clients/sim/core/world.h"
#include "clients/sim/loop/episode_trace.h"
#include "clients/sim/loop/failure_taxonomy.h"
#include "clients/sim/loop/kidnap.h"
#include "clients/sim/loop/localization_model.h"
#include "semnav/reasoning/v1/task.pb.h"

namespace semnav::sim::loop {

// Sensors for the loop: 160 x 120 depth (the 640 x 480 default scaled by 1/4, same field of
// view) keeps mapping's per-frame integration fast on two cores; detector pixel floor scaled alike.
SensorConfig LoopSensorConfig();

struct EpisodeSpec {
  World world;
  int start_index = 0;
  std::string target;        // as the operator says it: English or Chinese
  std::string target_label;  // the world's English label, for scoring; empty = target
  // The exploration strategy the task asks for (NEAREST_FRONTIER, COVERAGE_MAX,
  // SEMANTIC_FRONTIER, EROI_UTILITY) and the records' label; another name ("smoke") leaves the
  // gateway's configured default.
  std::string strategy;
  std::string robot_id = "sim-robot";
  int max_steps = 500;  // seed 004's episode budget
  double step_s = 0.5;  // simulated seconds per step (one frame per step)
  double success_radius = kDefaultSuccessRadius;
  uint64_t seed = 1;
  SensorConfig sensors = LoopSensorConfig();
  // Send the colour image on the robot session every step (CameraFrame), for EROI_UTILITY's
  // vision-model loop (seed 000); turns the RGB render on.
  bool camera_frames = false;
  // Called with each capture whose colour image goes to the gateway (the simulated VLM's frame
  // log records what the camera sent); unset = nothing.
  std::function<void(const SensorFrame&)> on_camera_frame;
  // Ground robots look down this much (rad) so low furniture in front of them reaches the map;
  // level (the Habitat agent's 0) leaves everything under 0.88 m unseen within ~1.9 m.
  double ground_camera_pitch = 0.35;
  // Thresholds that name a failed episode's cause (EpisodeRecord::failure_cause).
  FailureTaxonomyConfig taxonomy;
  // Losing the pose (docs/simulation.md): odometry drift is sensors.odometry; the localizer model
  // reports LOST when the believed pose departs from the truth; a kidnap carries the robot at
  // kidnap->at_s to a KidnapDestination drawn then, without telling it (unset = never).
  LocalizerConfig localizer;
  std::optional<KidnapConfig> kidnap;
  // The robot's landmark map for relocalization (map id = robot_id): "oracle" upserts the world's
  // objects (true centres, largest box extent, the detector's class embedding) before the
  // episode; "mapping" leaves it to mapping filling landmark maps from its scene graph; "" = none.
  std::string landmarks;
  // The report group (EpisodeRecord::group); empty = by the start's modality (ReportGroup).
  std::string report_group;
};

struct Endpoints {
  std::shared_ptr<grpc::Channel> gateway;
  std::shared_ptr<grpc::Channel> mapping;
  std::shared_ptr<grpc::Channel>
      planning;  // the robot's local planner (live map) and l_i (true map)
  std::shared_ptr<grpc::Channel>
      relocalization;  // landmark maps (EpisodeSpec::landmarks); null = none
};

struct EpisodeResult {
  EpisodeRecord record;
  std::string task_id;
  semnav::reasoning::v1::TaskStatus final_status = semnav::reasoning::v1::TASK_STATUS_UNSPECIFIED;
  std::string final_reason;
  bool stop_issued = false;  // the agent declared arrival: STOP at the end of a SUCCEEDED task
  int steps = 0;
  int collisions = 0;
  std::vector<Eigen::Vector2d> trajectory;  // true xy per step, for plots
  std::vector<Eigen::Vector2d> goals;       // distinct navigate goals the gateway sent, for plots
  std::string phase;                        // the task's latest phase, for progress displays
  // World::objects indices the robot's detector reported so far (true identity), for progress
  // displays and plots.
  std::set<int> seen_objects;
  // What the gateway decided and the robot answered, one line per change ("t=12.5s ..."),
  // so a failed episode can be read back.
  std::vector<std::string> timeline;
  // The same as values, for the failure taxonomy (record.failure_cause).
  EpisodeTrace trace;
};

}  // namespace semnav::sim::loop
