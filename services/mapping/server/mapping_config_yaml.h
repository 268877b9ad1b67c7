#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "services/common/config/config_reader.h"
#include "services/mapping/core/mapping_config.h"
#include "services/mapping/core/window_validation.h"
#include "services/mapping/landmarks/landmark_publisher.h"
#include "services/mapping/landmarks/scene_landmarks.h"

namespace semnav::mapping {

// Service-level settings around the core pipeline.
struct MappingServiceConfig {
  MappingConfig core;
  std::string store_directory = "var/maps";  // map store (created if missing)
  int watch_min_interval_ms = 200;           // grid/scene watch rate limit (floor for clients)
  double query_min_cosine = 0.2;             // QueryObjects default when the request says 0
  size_t idempotency_cache_size = 1024;      // remembered request_ids
  int occupancy_chunk_bytes = 1 << 20;       // GetOccupancy DataChunk size (protocol max 1 MiB)
  WindowLimits window_limits;                // GetGridMap / WatchGridMap window bounds
  double live_snapshot_interval_s = 5.0;     // crash-recovery snapshot of the live map; 0 = off
  // Frames integrate on these threads, off gRPC's few callback threads (which then answer grid
  // and scene reads at once); integration_nice > 0 lowers their priority below the service's.
  // Measured at 10 with 50 robots, the map took 70-80 s to settle instead of 25 s: 0.
  int integration_threads = 2;
  int integration_nice = 0;
  SceneLandmarkConfig landmarks;               // scene-graph instances -> relocalization landmarks
  LandmarkPublisherConfig landmark_publisher;  // where and how often they are pushed

  // The settings of `section` (keys below); a bad value, a failed check or an unknown key fails
  // with its key path (bad values are also recorded on `section`).
  static absl::StatusOr<MappingServiceConfig> FromYaml(ConfigReader& section);
};

// Reads the "mapping" YAML section. Keys (defaults in brackets):
//   octomap: {resolution_m [0.05], min_range_m [0.3], max_range_m [8], pixel_stride [1], threads
//   [2]} grid: {resolution_m [0.05], p_hit [0.7], p_miss [0.4], p_threshold [0.65], log_odds_min
//   [-2],
//          log_odds_max [3.5], foot_height_m [0.1], ceiling_height_m [2.3],
//          estimate_heights_after_frames [0 = off], obstacle_kernel [9],
//          robot_radius_m [0.25], change_log_size [256]}
//   semantic: {blur_min_laplacian_variance [100], erosion_kernel [5], erosion_keep_above [23.5],
//              mask_pixel_stride [2], depth_band_m [0.3], point_resolution_m [0.02],
//              radius_m [0.1], min_neighbours [5], opening_kernel [3], cap_voxel_m [0.05],
//              max_points_per_voxel [4], prune_growth [2], prune_min_points [4096],
//              instance_support_margin_m [0.25, negative = off],
//              instance_support_min_share [0.25]}
//   scene_graph: {ema_new_weight [0.3], embedding_min_cosine [0.8], embedding_max_distance_m [3],
//                 label_max_distance_m [1], prune_single_after_s [10], near_m [1.5],
//                 direction_margin_m [0.2], on_tolerance_m [0.15], region_radius_m [3]}
//   synonyms: {label: [other names]}   store_directory   watch_min_interval_ms   query_min_cosine
//   occupancy_chunk_bytes [1048576, in 1024..1048576]
//   max_window_cells [16777216]   max_abs_coordinate_m [100000]: grid-window request bounds
//   live_snapshot_interval_s [5, 0 = off]: crash-recovery snapshot in <store_directory>/live
//   integration_threads [2, in 1..16]   integration_nice [0, in 0..19]: the frame integration
//   threads and how much lower than the service's own their scheduling priority is
//   landmarks: {min_detections [3], labels [[]], embedding_dim [64], embedding_weight [0.5],
//               live_map_id [live], interval_s [2], deadline_ms [2000], settle_s [2.5],
//               push_with_frames [false: the simulator's lock-step stack only],
//               relocalization: {address [empty = no push], tls..., auth...}}: the landmark map
//               that builds itself from the scene graph (docs/algorithms/relocalization.md)

}  // namespace semnav::mapping
