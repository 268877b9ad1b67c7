#pragma once

#include "absl/status/statusor.h"
#include "services/common/client/channel.h"
#include "services/common/config/config_reader.h"
#include "services/planning/core/grid_planner.h"
#include "services/planning/core/jump_astar.h"
#include "services/planning/server/exploration_config.h"

namespace semnav::planning {

// Settings of semnav-planning (YAML section "planning"); defaults are the
// seed values.
struct PlanningConfig {
  // grid.occupied_percent: an OCCUPANCY cell at or above this blocks 2D
  // planning (seed 003 eq. 9, p_th = 0.65).
  int occupied_percent = 65;
  // grid.contact_radius_m: each contact of a PlanPathRequest (where the robot touched something)
  // becomes an obstacle disc of this radius before the footprint inflation; one 5 cm cell. A
  // wider disc closes doorways the robot brushed (a 0.9 m door with a 0.25 m robot leaves
  // 0.4 m for the centre line).
  double contact_radius_m = 0.05;
  // grid.unknown_is_free: unknown cells (255) count as free instead of blocked.
  bool unknown_is_free = false;
  // grid.max_low_probability_percent: seed 004 second-stage limit;
  // grid.start_snap_radius_m (0.5), grid.max_start_outside_m (1.0), grid.max_goal_outside_m
  // (1.0): how far an occupied start may snap and how far outside the grid a start / goal may lie;
  // clearance.{clearance_m (0.4), cost_scaling_per_m (3.0), cost_penalty (2.0)}: the Nav2-style
  // cost near obstacles.
  GridPlannerConfig grid_planner;
  // jump_astar.{alpha, beta, energy_unit_j, rolling_energy_j_per_m,
  // hover_power_w, flight_speed_mps}: seed 003 Table 1 and sec. 4.2.
  JumpAStarOptions jump_astar;
  // jump_astar.cache_mb: memory for prepared maps (region tables, landmarks)
  // kept for repeated queries, least recently used dropped first; ~1.9 bytes
  // per cell plus 32 once the landmarks exist (~22 MB at 800 x 800 cells).
  int jump_astar_cache_mb = 256;
  // jump_astar.flight_margin_m: a flying segment's altitude clears its tallest mapped obstacle by
  // this much (seed 003 gives none): half a 0.05 m voxel of the mapped top, depth noise on the
  // top, and room for the fly-roll robot's 0.05 m ground clearance, rounded up to 0.25 m.
  double flight_margin_m = 0.25;
  // exploration.*: frontier, coverage-max, semantic frontier, EROI settings.
  ExplorationConfig exploration;
  // trajectory.*: smoothing and time-allocation limits.
  TrajectoryConfig trajectory;
  // max_planning_time_ms: cap on any one search, whatever the deadline.
  int max_planning_time_ms = 5000;
  // deadline_margin_ms: a search stops this long before the call deadline,
  // so its typed TIMEOUT reply reaches the caller before gRPC expires the
  // call (a reply after the deadline is dropped).
  int deadline_margin_ms = 50;
  // worker_threads: searches run on this many threads, off the gRPC threads.
  int worker_threads = 2;
  // live_map_refresh_ahead: a call that finds a kept live grid older than this share of its
  // max_age_ms has it fetched again on a thread of its own, while this and later calls use the
  // kept one; 0 = a grid is fetched only when a call finds none young enough.
  double live_map_refresh_ahead = 0.5;
  // mapping: how to reach the mapping service for live-map requests.
  ClientOptions mapping = [] {
    ClientOptions options;
    options.address = "127.0.0.1:50051";  // deploy/local.yaml mapping port
    return options;
  }();

  static absl::StatusOr<PlanningConfig> FromYaml(ConfigReader& section);
};

}  // namespace semnav::planning
