#include "services/planning/server/planning_config.h"

#include <cmath>

namespace semnav::planning {

absl::StatusOr<PlanningConfig> PlanningConfig::FromYaml(ConfigReader& section) {
  PlanningConfig config;
  ConfigReader grid = section.Child("grid");
  grid.Read("occupied_percent", &config.occupied_percent)
      .Read("unknown_is_free", &config.unknown_is_free)
      .Read("max_low_probability_percent", &config.grid_planner.max_low_probability_percent)
      .Read("start_snap_radius_m", &config.grid_planner.start_snap_radius_m)
      .Read("max_start_outside_m", &config.grid_planner.max_start_outside_m)
      .Read("max_goal_outside_m", &config.grid_planner.max_goal_outside_m)
      .Read("max_free_goal_outside_m", &config.grid_planner.max_free_goal_outside_m)
      .Read("contact_radius_m", &config.contact_radius_m);
  ClearanceConfig& clearance = config.grid_planner.clearance;
  ConfigReader clear = section.Child("clearance");
  clear.Read("clearance_m", &clearance.clearance_m)
      .Read("cost_scaling_per_m", &clearance.cost_scaling_per_m)
      .Read("cost_penalty", &clearance.cost_penalty);
  clear.Check(std::isfinite(clearance.clearance_m) && clearance.clearance_m >= 0 &&
                  clearance.clearance_m <= 10,
              "clearance_m", "must be in [0, 10]");
  clear.Check(std::isfinite(clearance.cost_scaling_per_m) && clearance.cost_scaling_per_m >= 0 &&
                  clearance.cost_scaling_per_m <= 100,
              "cost_scaling_per_m", "must be in [0, 100]");
  clear.Check(std::isfinite(clearance.cost_penalty) && clearance.cost_penalty >= 0 &&
                  clearance.cost_penalty <= 100,
              "cost_penalty", "must be in [0, 100]");
  grid.Check(std::isfinite(config.grid_planner.start_snap_radius_m) &&
                 config.grid_planner.start_snap_radius_m >= 0 &&
                 config.grid_planner.start_snap_radius_m <= 5,
             "start_snap_radius_m", "must be in [0, 5]");
  grid.Check(std::isfinite(config.grid_planner.max_start_outside_m) &&
                 config.grid_planner.max_start_outside_m >= 0 &&
                 config.grid_planner.max_start_outside_m <= 10,
             "max_start_outside_m", "must be in [0, 10]");
  grid.Check(std::isfinite(config.grid_planner.max_goal_outside_m) &&
                 config.grid_planner.max_goal_outside_m >= 0 &&
                 config.grid_planner.max_goal_outside_m <= 10,
             "max_goal_outside_m", "must be in [0, 10]");
  grid.Check(std::isfinite(config.grid_planner.max_free_goal_outside_m) &&
                 config.grid_planner.max_free_goal_outside_m >= 0 &&
                 config.grid_planner.max_free_goal_outside_m <= 100,
             "max_free_goal_outside_m", "must be in [0, 100]");
  grid.Check(std::isfinite(config.contact_radius_m) && config.contact_radius_m >= 0 &&
                 config.contact_radius_m <= 1,
             "contact_radius_m", "must be in [0, 1]");
  grid.Check(config.occupied_percent >= 1 && config.occupied_percent <= 100, "occupied_percent",
             "must be in 1..100");
  grid.Check(config.grid_planner.max_low_probability_percent >= 0 &&
                 config.grid_planner.max_low_probability_percent <= 100,
             "max_low_probability_percent", "must be in 0..100");

  JumpAStarOptions& ja = config.jump_astar;
  ConfigReader jump = section.Child("jump_astar");
  jump.Read("alpha", &ja.alpha)
      .Read("beta", &ja.beta)
      .Read("energy_unit_j", &ja.energy_unit_j)
      .Read("rolling_energy_j_per_m", &ja.energy.rolling_j_per_m)
      .Read("hover_power_w", &ja.energy.hover_power_w)
      .Read("flight_speed_mps", &ja.energy.flight_speed_mps)
      .Read("cache_mb", &config.jump_astar_cache_mb)
      .Read("flight_margin_m", &config.flight_margin_m);
  jump.Check(ja.alpha >= 0 && ja.beta >= 0 && ja.alpha + ja.beta > 0, "alpha",
             "alpha and beta must be >= 0 and not both 0");
  jump.Check(ja.energy_unit_j > 0, "energy_unit_j", "must be > 0");
  jump.Check(ja.energy.rolling_j_per_m > 0, "rolling_energy_j_per_m", "must be > 0");
  jump.Check(ja.energy.hover_power_w > 0, "hover_power_w", "must be > 0");
  jump.Check(ja.energy.flight_speed_mps > 0, "flight_speed_mps", "must be > 0");
  jump.Check(std::isfinite(config.flight_margin_m) && config.flight_margin_m >= 0 &&
                 config.flight_margin_m <= 5,
             "flight_margin_m", "must be in [0, 5]");
  jump.Check(config.jump_astar_cache_mb >= 0 && config.jump_astar_cache_mb <= 65536, "cache_mb",
             "must be in 0..65536");

  ConfigReader exploration = section.Child("exploration");
  config.exploration.Read(exploration);
  ConfigReader trajectory = section.Child("trajectory");
  config.trajectory.Read(trajectory);

  section.Read("max_planning_time_ms", &config.max_planning_time_ms)
      .Read("deadline_margin_ms", &config.deadline_margin_ms)
      .Read("worker_threads", &config.worker_threads)
      .Read("live_map_refresh_ahead", &config.live_map_refresh_ahead);
  section.Check(config.max_planning_time_ms > 0, "max_planning_time_ms", "must be > 0");
  section.Check(config.deadline_margin_ms >= 0, "deadline_margin_ms", "must be >= 0");
  section.Check(config.worker_threads >= 1 && config.worker_threads <= 64, "worker_threads",
                "must be in 1..64");
  section.Check(config.live_map_refresh_ahead >= 0.0 && config.live_map_refresh_ahead <= 1.0,
                "live_map_refresh_ahead", "must be in [0, 1]");
  ConfigReader mapping = section.Child("mapping");
  config.mapping = ClientOptions::FromConfig(mapping, config.mapping);
  return config;
}

}  // namespace semnav::planning
