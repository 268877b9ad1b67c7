// What the gateway tells planning's SEMANTIC_FRONTIER strategy about the instruction (seed 002,
// 3.2.4 frontier score: 0.2 distance + 0.3 novelty + 0.2 language + 0.3 grounding): scene-graph
// objects with their language relevance to the target, their role in the target's relation chain
// and their commonsense co-occurrence with the target (the offline default's ConceptNet
// AtLocation prior, item 9), plus the places the robot already visited (topological memory).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "services/reasoning/core/label_matcher.h"
#include "services/reasoning/core/scene_graph.h"
#include "services/reasoning/core/subgoal.h"
#include "services/reasoning/core/topological_memory.h"

namespace semnav::reasoning {

// Commonsense co-occurrence of two objects, in [0, 1] (canonical lexicon names).
class CooccurrencePrior {
 public:
  virtual ~CooccurrencePrior() = default;
  virtual double Cooccurrence(std::string_view target, std::string_view label) const = 0;
  // Co-occurrence of the target with a room, known only by the objects seen in it together
  // (object-room co-occurrence without a room classifier). Default: the mean pairwise value, so
  // one stray object does not make a room; a prior that knows places overrides it.
  virtual double RoomCooccurrence(std::string_view target,
                                  const std::vector<std::string>& labels) const;
};

struct ExplorationHint {
  std::string label;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // map frame, metres
  double relevance = 0.0;                              // label match with the target, [0, 1]
  double relation = 0.0;      // 1 when the object is the anchor of the target's relation
  double cooccurrence = 0.0;  // commonsense co-occurrence with the target, [0, 1]
};

// The operator's axis-aligned search area, map frame, metres: exploration stays inside it.
struct SearchArea {
  Eigen::Vector2d min = Eigen::Vector2d::Zero();
  Eigen::Vector2d max = Eigen::Vector2d::Zero();
};

struct ExplorationContext {
  // Objects with some non-zero term, then one hint per scene region of >= 2 objects (label
  // "region:<id>", at its objects' mean, co-occurrence = RoomCooccurrence of its objects).
  std::vector<ExplorationHint> objects;
  std::vector<Eigen::Vector3d> visited;  // topological memory nodes
  // EROI_UTILITY (seed 000): semantic value per EROI column of edge `eroi_edge_m` over the
  // rectangle [eroi_window_min, eroi_window_max], row-major with x fastest; empty = none.
  std::vector<double> eroi_values;
  Eigen::Vector2d eroi_window_min = Eigen::Vector2d::Zero();
  Eigen::Vector2d eroi_window_max = Eigen::Vector2d::Zero();
  double eroi_edge_m = 0.0;
  // Where the vision model said it saw the target (EroiSearch::sightings), map frame; the robot
  // looks from eroi_inspect_distance_m before the next exploration goal (sighting_goal.h).
  std::vector<Eigen::Vector3d> eroi_sightings;
  double eroi_inspect_distance_m = 0.0;  // 0 = sightings are not looked at
  // Set (by PerTaskPathPlanner): planning answers where to look at this sighting from, from
  // look_distance_m, instead of an exploration goal.
  std::optional<Eigen::Vector3d> look_at;
  double look_distance_m = 0.0;
  std::optional<SearchArea> search_area;  // unset = the whole map
};

// `prior` and `memory` may be null (no co-occurrence / no visited places). A room target gives
// no object terms (rooms are found through regions, not co-occurrence).
ExplorationContext BuildExplorationContext(const TargetSpec& target, const SceneGraph& graph,
                                           const LabelMatcher& matcher,
                                           const CooccurrencePrior* prior,
                                           const TopologicalMemory* memory);

}  // namespace semnav::reasoning
