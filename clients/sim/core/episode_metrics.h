#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/world.h"

// Episode scoring exactly as seed 004 section 3.2 (after Anderson et al. 2018):
//   SR  = (1/N) sum S_i
//   SPL = (1/N) sum S_i * l_i / max(p_i, l_i)
//   DTG = (1/N) sum d_i
// S_i: the agent issued stop inside the target's success region (SuccessRegion: within the
// success radius, 1 m in seed 004, of an instance's footprint by geodesic distance, so never
// through a wall); l_i: shortest path length from the start to that region (from the planner
// on the true map, given by the caller); p_i: length of the path taken; d_i: horizontal
// distance to the nearest instance's footprint when the episode ended.
namespace semnav::sim {

inline constexpr double kDefaultSuccessRadius = 1.0;

// Horizontal distance from `position` to the nearest footprint of an instance labelled
// `label` (0 inside it); infinity when the world has none.
double DistanceToNearestInstance(const World& world, std::string_view label,
                                 const Eigen::Vector2d& position);

// Where an episode counts as a success, in the style of Habitat's object view points (Batra
// et al. 2020, "ObjectNav revisited"): the cells of the robot body's true occupancy grid whose
// geodesic distance to the footprint of an instance of the label is at most the success radius.
// The geodesic distance of a free cell is the shortest 8-connected path over free cells to a
// view cell plus the view cell's straight distance to the footprint's nearest point it sees; a
// view cell is a free cell from which a straight line to a point of a footprint within the
// radius, at the instance's mid-height, meets no solid (some of the object in view, not
// necessarily its nearest point). Solids that overlap the instance's footprint and are not
// structure (the table under a cup, the shelf holding a book) do not block; walls and buildings
// always do. So a target 0.5 m behind a thin wall is 0.5 m away only from its own side.
class SuccessRegion {
 public:
  static SuccessRegion Build(const World& world, std::string_view label,
                             const GroundTruthGrid& body_grid,
                             double success_radius = kDefaultSuccessRadius);

  // Geodesic distance (m) from `p` to the nearest footprint; infinity when it exceeds the
  // radius or no instance is reachable. A point in an occupied cell (the body raster marks
  // cells within half a cell of the dilated solids) takes its best free neighbour within two
  // cells plus the step to it.
  double GeodesicDistance(const Eigen::Vector2d& p) const;
  bool Contains(const Eigen::Vector2d& p) const { return GeodesicDistance(p) <= radius_; }
  double radius() const { return radius_; }
  // True when no cell is in the region (no instance, or none reachable by the body).
  bool empty() const { return empty_; }

 private:
  GroundTruthGrid geometry_;     // origin, resolution and size of the body grid; no cells
  std::vector<uint8_t> free_;    // 1 where the body grid is free
  std::vector<float> distance_;  // geodesic distance per cell, infinity outside the region
  double radius_ = kDefaultSuccessRadius;
  bool empty_ = true;
};

struct StopOutcome {
  bool success = false;
  double distance_to_goal_m = 0.0;
};
// Scores where the episode ended: a success when the stop was issued inside `region` (built
// for `target_label`). `stop_issued` false (budget exhausted) never succeeds. The distance is
// the horizontal distance to the nearest footprint (DistanceToNearestInstance).
StopOutcome ScoreStop(const World& world, const SuccessRegion& region,
                      std::string_view target_label, const Eigen::Vector2d& final_position,
                      bool stop_issued);

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
  // Why a failed episode failed (the loop's failure taxonomy, e.g. "budget_spent_exploring");
  // empty for a success.
  std::string failure_cause;
  // What the model served this episode (known with the simulated VLM; 0 otherwise): tokens in
  // and out, the simulated seconds its answers took, and the answers about an image.
  int64_t model_tokens = 0;
  double model_wait_s = 0.0;
  int vision_calls = 0;
  int start_index = -1;  // World::starts index: pairs an episode with the same one in another group
  // Losing the pose (drift / kidnapped groups): losses (a kidnap, or the localizer reporting LOST),
  // recoveries (a gateway correction closing a loss) with each one's time since the loss and the
  // believed pose's error right after it, and the error at the episode's end.
  int losses = 0;
  std::vector<double> recovery_times_s{};
  std::vector<double> recovery_errors_m{};
  std::vector<double> recovery_errors_deg{};
  double final_pose_error_m = 0.0;
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
  double model_tokens = 0.0;     // mean per episode
  double model_wait_s = 0.0;     // mean per episode, simulated seconds
  double vision_calls = 0.0;     // mean per episode
  double fast_path_share = 0.0;  // fast-path resolutions / all resolutions (0 if none)
  // Failed episodes per cause (EpisodeRecord::failure_cause; "unclassified" when empty).
  std::map<std::string, int> failures;
};

// One summary per strategy, in order of first appearance.
std::vector<StrategySummary> SummariseByStrategy(const std::vector<EpisodeRecord>& records);

}  // namespace semnav::sim
