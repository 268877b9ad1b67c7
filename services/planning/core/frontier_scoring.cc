#include "services/planning/core/frontier_scoring.h"

#include <algorithm>
#include <cmath>

namespace semnav::planning {
namespace {

double Distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

// cos of the angle between robot->a and robot->b, clamped at 0.
double Alignment(Point2 robot, Point2 a, Point2 b) {
  const double ax = a.x - robot.x;
  const double ay = a.y - robot.y;
  const double bx = b.x - robot.x;
  const double by = b.y - robot.y;
  const double norm = std::hypot(ax, ay) * std::hypot(bx, by);
  return norm > 0.0 ? std::max(0.0, (ax * bx + ay * by) / norm) : 0.0;
}

}  // namespace

std::vector<FrontierScore> ScoreFrontiers(const std::vector<FrontierCandidate>& frontiers,
                                          Point2 robot, const std::vector<Point2>& visited,
                                          const std::vector<ScoredObject>& objects,
                                          const FrontierScoreConfig& config) {
  double farthest = 0.0;
  for (const FrontierCandidate& f : frontiers) farthest = std::max(farthest, f.path_distance_m);
  std::vector<FrontierScore> scores;
  for (const FrontierCandidate& f : frontiers) {
    FrontierScore s;
    if (f.path_distance_m >= 0.0) {
      s.distance = farthest > 0.0 ? 1.0 - f.path_distance_m / farthest : 1.0;
    }
    s.novelty = 1.0;
    for (const Point2& v : visited) {
      s.novelty = std::min(s.novelty, Distance(v, f.centroid) / config.novelty_radius_m);
    }
    double gradient = 0.0;
    double relation = 0.0;
    double cooccurrence = 0.0;
    for (const ScoredObject& o : objects) {
      const bool near = Distance(o.position, f.centroid) <= config.language_radius_m;
      if (near) {
        s.language = std::max(s.language, o.relevance);
        cooccurrence = std::max(cooccurrence, o.cooccurrence);
      }
      const double aligned = Alignment(robot, f.centroid, o.position);
      gradient = std::max(gradient, o.relevance * aligned);
      relation = std::max(relation, o.relation * aligned);
    }
    s.gradient = gradient;
    s.relation = relation;
    s.cooccurrence = cooccurrence;
    s.grounding = config.gradient_weight * gradient + config.relation_weight * relation +
                  config.cooccurrence_weight * cooccurrence;
    s.total = config.distance_weight * s.distance + config.novelty_weight * s.novelty +
              config.language_weight * s.language + config.grounding_weight * s.grounding;
    scores.push_back(s);
  }
  return scores;
}

}  // namespace semnav::planning
