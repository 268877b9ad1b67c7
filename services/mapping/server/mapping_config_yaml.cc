#include "services/mapping/server/mapping_config_yaml.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "absl/strings/strip.h"
#include "services/common/status/field_error.h"

namespace semnav::mapping {

absl::StatusOr<MappingServiceConfig> MappingServiceConfig::FromYaml(ConfigReader& section) {
  MappingServiceConfig config;
  MappingConfig& c = config.core;

  ConfigReader octomap = section.Child("octomap");
  octomap.Read("resolution_m", &c.octomap_resolution_m)
      .Read("min_range_m", &c.range.min_m)
      .Read("max_range_m", &c.range.max_m)
      .Read("pixel_stride", &c.pixel_stride)
      .Read("threads", &c.threads);
  octomap.Check(c.octomap_resolution_m > 0.0, "resolution_m", "must be > 0");
  octomap.Check(c.range.min_m >= 0.0 && c.range.max_m > c.range.min_m, "max_range_m",
                "must be > min_range_m >= 0");
  octomap.Check(c.pixel_stride >= 1, "pixel_stride", "must be >= 1");
  octomap.Check(c.threads >= 1 && c.threads <= 64, "threads", "must be in [1, 64]");

  ConfigReader grid = section.Child("grid");
  int change_log = static_cast<int>(c.grid_change_log_size);
  grid.Read("resolution_m", &c.grid.resolution_m)
      .Read("p_hit", &c.grid.p_hit)
      .Read("p_miss", &c.grid.p_miss)
      .Read("p_threshold", &c.grid.p_threshold)
      .Read("log_odds_min", &c.grid.log_odds_min)
      .Read("log_odds_max", &c.grid.log_odds_max)
      .Read("foot_height_m", &c.heights.foot_m)
      .Read("ceiling_height_m", &c.heights.ceiling_m)
      .Read("body_height_m", &c.heights.body_m)
      .Read("estimate_heights_after_frames", &c.estimate_heights_after_frames)
      .Read("obstacle_kernel", &c.layers.obstacle_kernel)
      .Read("robot_radius_m", &c.layers.robot_radius_m)
      .Read("change_log_size", &change_log);
  grid.Check(c.grid.resolution_m > 0.0, "resolution_m", "must be > 0");
  grid.Check(c.grid.p_hit > 0.5 && c.grid.p_hit < 1.0, "p_hit", "must be in (0.5, 1)");
  grid.Check(c.grid.p_miss > 0.0 && c.grid.p_miss < 0.5, "p_miss", "must be in (0, 0.5)");
  grid.Check(c.grid.p_threshold > 0.0 && c.grid.p_threshold < 1.0, "p_threshold",
             "must be in (0, 1)");
  grid.Check(c.grid.log_odds_min < 0.0 && c.grid.log_odds_max > 0.0, "log_odds_max",
             "need log_odds_min < 0 < log_odds_max");
  grid.Check(c.heights.ceiling_m > c.heights.foot_m, "ceiling_height_m", "must be > foot_height_m");
  grid.Check(c.heights.body_m >= 0.0 && c.heights.body_m <= c.heights.ceiling_m - c.heights.foot_m,
             "body_height_m", "must be in [0, ceiling_height_m - foot_height_m]");
  grid.Check(c.estimate_heights_after_frames >= 0, "estimate_heights_after_frames",
             "must be >= 0 (0 = off)");
  grid.Check(c.layers.obstacle_kernel >= 1 && c.layers.obstacle_kernel % 2 == 1, "obstacle_kernel",
             "must be odd and >= 1");
  grid.Check(c.layers.robot_radius_m >= 0.0, "robot_radius_m", "must be >= 0");
  grid.Check(change_log >= 1, "change_log_size", "must be >= 1");
  c.grid_change_log_size = static_cast<size_t>(std::max(change_log, 1));

  ConfigReader scan = section.Child("scan_match");
  ScanMatchConfig& m = c.scan_match;
  GlobalMatchConfig& g = c.global_scan_match;
  int max_cells = static_cast<int>(c.lost_scan_max_cells);
  int global_max_cells = static_cast<int>(c.global_scan_match_max_cells);
  scan.Read("linear_window_m", &m.linear_window_m)
      .Read("angular_window_rad", &m.angular_window_rad)
      .Read("angular_step_rad", &m.angular_step_rad)
      .Read("sigma_m", &m.sigma_m)
      .Read("min_score", &m.min_score)
      .Read("min_gain", &m.min_gain)
      .Read("min_scan_cells", &m.min_scan_cells)
      .Read("max_cells", &max_cells)
      .Read("global_angular_step_rad", &g.angular_step_rad)
      .Read("global_min_score", &g.min_score)
      .Read("global_min_misfit_ratio", &g.min_misfit_ratio)
      .Read("global_max_ray_conflicts", &g.max_ray_conflicts)
      .Read("global_ray_emerge_cells", &g.ray_emerge_cells)
      .Read("global_max_cells", &global_max_cells);
  // The search visits (2 w / r + 1)^2 (2 a / s + 1) poses: the bounds keep it under ~10^6.
  scan.Check(m.linear_window_m >= 0.0 && m.linear_window_m <= 2.0, "linear_window_m",
             "must be in [0, 2]");
  scan.Check(m.angular_window_rad >= 0.0 && m.angular_window_rad <= 0.8, "angular_window_rad",
             "must be in [0, 0.8]");
  scan.Check(m.angular_step_rad >= 0.002 && m.angular_step_rad <= 0.2, "angular_step_rad",
             "must be in [0.002, 0.2]");
  scan.Check(m.sigma_m > 0.0 && m.sigma_m <= 1.0, "sigma_m", "must be in (0, 1]");
  scan.Check(m.min_score >= 0.0 && m.min_score <= 1.0, "min_score", "must be in [0, 1]");
  scan.Check(m.min_gain >= 0.0 && m.min_gain <= 1.0, "min_gain", "must be in [0, 1]");
  if (c.grid.resolution_m > 0.0 && m.angular_step_rad > 0.0) {
    const double side = 2.0 * std::round(m.linear_window_m / c.grid.resolution_m) + 1.0;
    const double turns = 2.0 * std::floor(m.angular_window_rad / m.angular_step_rad) + 1.0;
    scan.Check(side * side * turns <= 250000.0, "linear_window_m",
               "the window over the grid resolution and the angular step visits more than "
               "250,000 poses");
  }
  scan.Check(m.min_scan_cells >= 1, "min_scan_cells", "must be >= 1");
  scan.Check(max_cells >= 1 && max_cells <= 200000, "max_cells", "must be in [1, 200000]");
  c.lost_scan_max_cells = static_cast<size_t>(std::clamp(max_cells, 1, 200000));
  scan.Check(g.angular_step_rad >= 0.01 && g.angular_step_rad <= 0.2, "global_angular_step_rad",
             "must be in [0.01, 0.2]");
  scan.Check(g.min_score >= 0.0 && g.min_score <= 1.0, "global_min_score", "must be in [0, 1]");
  scan.Check(g.min_misfit_ratio >= 1.0 && g.min_misfit_ratio <= 100.0, "global_min_misfit_ratio",
             "must be in [1, 100]");
  scan.Check(g.max_ray_conflicts >= 0.0 && g.max_ray_conflicts <= 1.0, "global_max_ray_conflicts",
             "must be in [0, 1]");
  scan.Check(g.ray_emerge_cells >= 0 && g.ray_emerge_cells <= 20, "global_ray_emerge_cells",
             "must be in [0, 20]");
  scan.Check(global_max_cells >= 1 && global_max_cells <= 16'000'000, "global_max_cells",
             "must be in [1, 16000000]");
  c.global_scan_match_max_cells = static_cast<size_t>(std::clamp(global_max_cells, 1, 16'000'000));

  ConfigReader semantic = section.Child("semantic");
  semantic.Read("blur_min_laplacian_variance", &c.blur_min_laplacian_variance)
      .Read("erosion_kernel", &c.lift.erosion_kernel)
      .Read("erosion_keep_above", &c.lift.erosion_keep_above)
      .Read("mask_pixel_stride", &c.lift.pixel_stride)
      .Read("depth_band_m", &c.lift.depth_band_m)
      .Read("point_resolution_m", &c.semantic.point_resolution_m)
      .Read("radius_m", &c.semantic.radius_m)
      .Read("min_neighbours", &c.semantic.min_neighbours)
      .Read("opening_kernel", &c.semantic.opening_kernel)
      .Read("cap_voxel_m", &c.semantic.cap_voxel_m)
      .Read("max_points_per_voxel", &c.semantic.max_points_per_voxel)
      .Read("prune_growth", &c.semantic.prune_growth)
      .Read("prune_min_points", &c.semantic.prune_min_points)
      .Read("instance_support_margin_m", &c.semantic.instance_support_margin_m)
      .Read("instance_support_min_share", &c.semantic.instance_support_min_share);
  semantic.Check(c.blur_min_laplacian_variance >= 0.0, "blur_min_laplacian_variance",
                 "must be >= 0");
  semantic.Check(c.lift.erosion_kernel >= 1 && c.lift.erosion_kernel % 2 == 1, "erosion_kernel",
                 "must be odd and >= 1");
  semantic.Check(c.lift.pixel_stride >= 1, "mask_pixel_stride", "must be >= 1");
  semantic.Check(c.lift.depth_band_m > 0.0, "depth_band_m", "must be > 0");
  semantic.Check(c.semantic.point_resolution_m > 0.0, "point_resolution_m", "must be > 0");
  semantic.Check(c.semantic.radius_m > 0.0f, "radius_m", "must be > 0");
  semantic.Check(c.semantic.min_neighbours >= 0, "min_neighbours", "must be >= 0");
  semantic.Check(c.semantic.opening_kernel >= 1, "opening_kernel", "must be >= 1");
  semantic.Check(c.semantic.cap_voxel_m > 0.0, "cap_voxel_m", "must be > 0");
  semantic.Check(c.semantic.max_points_per_voxel >= 1, "max_points_per_voxel", "must be >= 1");
  // Below 1.1 a label would be pruned (a KD-tree pass over its points) almost every frame.
  semantic.Check(c.semantic.prune_growth >= 1.1 && c.semantic.prune_growth <= 1000.0,
                 "prune_growth", "must be in [1.1, 1000]");
  semantic.Check(c.semantic.prune_min_points >= 1, "prune_min_points", "must be >= 1");
  semantic.Check(std::isfinite(c.semantic.instance_support_margin_m) &&
                     c.semantic.instance_support_margin_m <= 10.0,
                 "instance_support_margin_m", "must be finite and <= 10 (negative = off)");
  semantic.Check(
      c.semantic.instance_support_min_share >= 0.0 && c.semantic.instance_support_min_share <= 1.0,
      "instance_support_min_share", "must be in [0, 1]");

  ConfigReader scene = section.Child("scene_graph");
  SceneGraphConfig& s = c.scene;
  scene.Read("ema_new_weight", &s.ema_new_weight)
      .Read("embedding_min_cosine", &s.embedding_min_cosine)
      .Read("embedding_max_distance_m", &s.embedding_max_distance_m)
      .Read("label_max_distance_m", &s.label_max_distance_m)
      .Read("prune_single_after_s", &s.prune_single_after_s)
      .Read("untrusted_lookback_s", &s.untrusted_lookback_s)
      .Read("near_m", &s.relations.near_m)
      .Read("direction_margin_m", &s.relations.direction_margin_m)
      .Read("on_tolerance_m", &s.relations.on_tolerance_m)
      .Read("region_radius_m", &s.relations.region_radius_m);
  scene.Check(s.ema_new_weight > 0.0 && s.ema_new_weight <= 1.0, "ema_new_weight",
              "must be in (0, 1]");
  scene.Check(s.embedding_min_cosine >= -1.0 && s.embedding_min_cosine <= 1.0,
              "embedding_min_cosine", "must be in [-1, 1]");
  scene.Check(s.prune_single_after_s > 0.0, "prune_single_after_s", "must be > 0");
  scene.Check(s.untrusted_lookback_s >= 0.0 && s.untrusted_lookback_s <= 60.0,
              "untrusted_lookback_s", "must be in [0, 60]");
  scene.Check(s.relations.near_m > 0.0 && s.relations.region_radius_m > 0.0, "region_radius_m",
              "radii must be > 0");
  ConfigReader existence = scene.Child("existence");
  ExistenceConfig& e = s.existence;
  existence.Read("enabled", &e.enabled)
      .Read("max_range_m", &e.max_range_m)
      .Read("min_view_fraction", &e.min_view_fraction)
      .Read("image_margin", &e.image_margin)
      .Read("occlusion_tolerance_m", &e.occlusion_tolerance_m)
      .Read("min_misses", &e.min_misses)
      .Read("max_misses_per_detection", &e.max_misses_per_detection);
  existence.Check(e.max_range_m > 0.0 && e.max_range_m <= 100.0, "max_range_m",
                  "must be in (0, 100]");
  existence.Check(e.min_view_fraction >= 0.0 && e.min_view_fraction <= 1.0, "min_view_fraction",
                  "must be in [0, 1]");
  existence.Check(e.image_margin >= 0.0 && e.image_margin < 0.5, "image_margin",
                  "must be in [0, 0.5)");
  existence.Check(e.occlusion_tolerance_m >= 0.0 && e.occlusion_tolerance_m <= 10.0,
                  "occlusion_tolerance_m", "must be in [0, 10]");
  existence.Check(e.min_misses >= 1, "min_misses", "must be >= 1");
  existence.Check(e.max_misses_per_detection > 0.0 && e.max_misses_per_detection <= 1000.0,
                  "max_misses_per_detection", "must be in (0, 1000]");

  for (const std::string& label : section.Child("synonyms").Keys()) {
    std::vector<std::string> names;
    section.Child("synonyms").Read(label, &names);
    c.synonyms[label] = names;
  }
  section.Read("store_directory", &config.store_directory)
      .Read("watch_min_interval_ms", &config.watch_min_interval_ms)
      .Read("query_min_cosine", &config.query_min_cosine)
      .Read("occupancy_chunk_bytes", &config.occupancy_chunk_bytes)
      .Read("max_window_cells", &config.window_limits.max_cells)
      .Read("max_abs_coordinate_m", &config.window_limits.max_abs_coordinate_m)
      .Read("live_snapshot_interval_s", &config.live_snapshot_interval_s)
      .Read("integration_threads", &config.integration_threads)
      .Read("integration_nice", &config.integration_nice);
  section.Check(!config.store_directory.empty(), "store_directory", "must not be empty");
  section.Check(config.watch_min_interval_ms >= 10, "watch_min_interval_ms", "must be >= 10");
  section.Check(config.occupancy_chunk_bytes >= 1024 && config.occupancy_chunk_bytes <= (1 << 20),
                "occupancy_chunk_bytes", "must be in [1024, 1048576]");
  section.Check(config.window_limits.max_cells >= 1, "max_window_cells", "must be >= 1");
  section.Check(config.live_snapshot_interval_s >= 0 && config.live_snapshot_interval_s <= 3600,
                "live_snapshot_interval_s", "must be in [0, 3600]");
  section.Check(config.window_limits.max_abs_coordinate_m > 0, "max_abs_coordinate_m",
                "must be > 0");
  section.Check(config.integration_threads >= 1 && config.integration_threads <= 16,
                "integration_threads", "must be in [1, 16]");
  section.Check(config.integration_nice >= 0 && config.integration_nice <= 19, "integration_nice",
                "must be in [0, 19]");

  ConfigReader landmarks = section.Child("landmarks");
  SceneLandmarkConfig& l = config.landmarks;
  LandmarkPublisherConfig& p = config.landmark_publisher;
  landmarks.Read("min_detections", &l.min_detections)
      .Read("labels", &l.labels)
      .Read("embedding_dim", &l.embedding_dim)
      .Read("embedding_weight", &l.embedding_weight)
      .Read("live_map_id", &p.live_map_id)
      .Read("interval_s", &p.interval_s)
      .Read("deadline_ms", &p.deadline_ms)
      .Read("settle_s", &p.settle_s)
      .Read("push_with_frames", &p.push_with_frames);
  // Without the section no relocalization service is used (FromConfig wants an address).
  if (landmarks.Has("relocalization")) {
    ConfigReader relocalization = landmarks.Child("relocalization");
    p.relocalization = ClientOptions::FromConfig(relocalization, p.relocalization);
  }
  // Core names the key in the error's payload; the reader reports it as "landmarks.<key>".
  for (const absl::Status& s :
       {ValidateSceneLandmarkConfig(l), ValidateLandmarkPublisherConfig(p)}) {
    if (s.ok()) continue;
    const std::string key = ErrorField(s).value_or("landmarks");
    absl::string_view why = s.message();
    absl::ConsumePrefix(&why, key + ": ");
    landmarks.Check(false, key, std::string(why));
  }
  if (absl::Status s = section.Finish(); !s.ok()) return s;
  return config;
}

}  // namespace semnav::mapping
