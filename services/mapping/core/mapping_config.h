#pragma once

#include <map>
#include <string>
#include <vector>

#include "services/mapping/core/depth_projection.h"
#include "services/mapping/core/detection_lifter.h"
#include "services/mapping/core/grid_layers.h"
#include "services/mapping/core/hierarchical_grid.h"
#include "services/mapping/core/scan_matcher.h"
#include "services/mapping/core/scene_graph.h"
#include "services/mapping/core/semantic_map.h"

namespace semnav::mapping {

// Every tunable of the mapping pipeline with its default (YAML section "mapping", see
// services/mapping/server/mapping_config_yaml.h for the keys).
struct MappingConfig {
  double octomap_resolution_m = 0.05;  // OctoMap voxel edge R_o
  DepthRange range;                    // 0.3 - 8 m
  int pixel_stride = 1;                // depth pixels used per row/column (1 = all)
  int threads = 2;                     // ray-casting threads
  HierarchicalGridConfig grid;         // R_g, p_hit, p_miss, p_th = 0.65
  ClimbingHeights heights;             // h_f, h_c
  // > 0: after this many accepted frames, replace h_f/h_c by EstimateHeights on the map (the
  // seed reads the ceiling at start-up) and rebuild the grid; 0: keep the configured heights.
  int estimate_heights_after_frames = 0;
  GridLayersConfig layers;                     // 9x9 obstacle kernel, robot radius
  double blur_min_laplacian_variance = 100.0;  // seed 002 blur filter (0 disables)
  LiftConfig lift;
  SemanticMapConfig semantic;
  SceneGraphConfig scene;
  size_t grid_change_log_size = 256;  // grid changes remembered for resumable watches
  // A lost robot's look-around against the grid (MatchLostScan), near a coarse pose and global.
  ScanMatchConfig scan_match;
  GlobalMatchConfig global_scan_match;
  // The global match's raster at most (1,000,000 cells = 50 x 50 m at 5 cm: ~1 s on one core).
  size_t global_scan_match_max_cells = 1'000'000;
  // Obstacle cells kept per lost robot (5 cm cells: 20,000 = 1 km of wall, 160 KiB).
  size_t lost_scan_max_cells = 20000;
  std::map<std::string, std::vector<std::string>> synonyms;  // query label -> other names
};

}  // namespace semnav::mapping
