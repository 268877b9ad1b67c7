#ifndef SEMNAV_CLIENTS_SIM_CORE_EPISODE_METRICS_H_
#define SEMNAV_CLIENTS_SIM_CORE_EPISODE_METRICS_H_

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "clients/sim/core/world.h"

// Episode scoring exactly as seed 004 section 3.2 (after Anderson et al. 2018):
//   SR  = (1/N) sum S_i
//   SPL = (1/N) sum S_i * l_i / max(p_i, l_i)
//   DTG = (1/N) sum d_i
// S_i: the agent issued stop within the success radius (1 m in seed 004) of the target;
// l_i: shortest path length from the start to the nearest reachable target instance (from
// the planner on the true map, given by the caller); p_i: length of the path taken;
// d_i: distance to the target when stop was issued.
namespace semnav::sim {

inline constexpr double kDefaultSuccessRadius = 1.0;

// Horizontal distance from `position` to the nearest footprint of an instance labelled
// `label` (0 inside it); infinity when the world has none.
double DistanceToNearestInstance(const World& world, std::string_view label,
                                 const Eigen::Vector2d& position);

struct StopOutcome {
  bool success = false;
  double distance_to_goal_m = 0.0;
};
// Scores where the episode ended. `stop_issued` false (budget exhausted) never succeeds; its
// distance is then measured at the final position.
StopOutcome ScoreStop(const World& world, std::string_view target_label,
                      const Eigen::Vector2d& final_position, bool stop_issued,
                      double success_radius = kDefaultSuccessRadius);

// S * l / max(p, l); 0 when l <= 0 and p <= 0 would make it undefined.
double SuccessWeightedPathLength(bool success, double shortest_m, double path_m);

struct EpisodeRecord {
  std::string strategy;
  std::string world;
  std::string target;
  bool success = false;
  double shortest_path_m = 0.0;     // l_i
  double path_m = 0.0;              // p_i
  double distance_to_goal_m = 0.0;  // d_i
  double time_s = 0.0;
  double energy_j = 0.0;
  int model_calls = 0;
  int goals_resolved = 0;   // goal resolutions the gateway made
  int goals_fast_path = 0;  // of which on the fast path
  std::string group;        // the report section: indoor, outdoor or flyroll (by modality)
};

// The report section of an episode by the robot's modality: ground = "indoor", uav = "outdoor",
// fly_roll = "flyroll".
std::string ReportGroup(Modality modality);

struct StrategySummary {
  std::string strategy;
  int episodes = 0;
  double sr = 0.0;
  double spl = 0.0;
  double dtg_m = 0.0;
  double path_m = 0.0;           // mean
  double time_s = 0.0;           // mean
  double energy_j = 0.0;         // mean
  double model_calls = 0.0;      // mean per episode
  double fast_path_share = 0.0;  // fast-path resolutions / all resolutions (0 if none)
};

// One summary per strategy, in order of first appearance.
std::vector<StrategySummary> SummariseByStrategy(const std::vector<EpisodeRecord>& records);

}  // namespace semnav::sim

#endif  // SEMNAV_CLIENTS_SIM_CORE_EPISODE_METRICS_H_
