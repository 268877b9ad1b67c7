#pragma once

#include <vector>

#include "services/planning/core/trajectory.h"

namespace semnav::planning {

// An object the caller relates to the instruction (from the scene graph
// and the reasoning service), all scores in [0, 1].
struct ScoredObject {
  Point2 position;         // metres
  double relevance = 0.0;  // language match with the instruction target
  double relation = 0.0;  // on the instruction's relation chain (e.g. the table for "cup on table")
  double cooccurrence = 0.0;  // commonsense co-occurrence with the target (e.g. ConceptNet)
};

// Seed 002 sec. 3.2.4 (MTU3D-style) weights; the seed fixes the four term
// weights, not how the three grounding signals combine (equal by default).
struct FrontierScoreConfig {
  double distance_weight = 0.2;
  double novelty_weight = 0.3;
  double language_weight = 0.2;
  double grounding_weight = 0.3;
  double gradient_weight = 1.0 / 3;      // spatial gradient
  double relation_weight = 1.0 / 3;      // relation chain
  double cooccurrence_weight = 1.0 / 3;  // commonsense co-occurrence
  double language_radius_m = 3.0;        // objects this close count as "near" a frontier
  double novelty_radius_m = 3.0;         // visited places this close make a frontier stale
};

struct FrontierCandidate {
  Point2 centroid;             // metres
  double path_distance_m = 0;  // from the robot; < 0 = unreachable
};

struct FrontierScore {
  double distance = 0.0;   // 1 nearest .. 0 farthest (0 when unreachable)
  double novelty = 0.0;    // 1 far from every visited place
  double language = 0.0;   // best relevance of objects near the frontier
  double grounding = 0.0;  // weighted gradient + relation + co-occurrence
  double gradient = 0.0;   // the three grounding signals, each in [0, 1]
  double relation = 0.0;
  double cooccurrence = 0.0;
  double total = 0.0;  // 0.2 distance + 0.3 novelty + 0.2 language + 0.3 grounding
};

// SEMANTIC_FRONTIER: scores each frontier. Distance: 1 - d / d_max over the
// reachable candidates. Novelty: min(1, distance to the nearest visited
// place / novelty_radius). Language: max relevance of objects within
// language_radius of the centroid. Grounding: spatial gradient (relevant
// objects in the frontier's direction from the robot, relevance x cos of
// the angle, negative cos = 0), relation chain (the same with `relation`),
// and co-occurrence (max co-occurrence of objects near the frontier).
std::vector<FrontierScore> ScoreFrontiers(const std::vector<FrontierCandidate>& frontiers,
                                          Point2 robot, const std::vector<Point2>& visited,
                                          const std::vector<ScoredObject>& objects,
                                          const FrontierScoreConfig& config);

}  // namespace semnav::planning
