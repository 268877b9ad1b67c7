#include "clients/sim/core/episode_metrics.h"

#include <algorithm>
#include <limits>

#include "clients/sim/core/geometry2d.h"

namespace semnav::sim {

double DistanceToNearestInstance(const World& world, std::string_view label,
                                 const Eigen::Vector2d& position) {
  double best = std::numeric_limits<double>::infinity();
  for (const ObjectInstance& object : world.objects) {
    if (object.label == label) best = std::min(best, DistanceToBoxFootprint(object.box, position));
  }
  return best;
}

StopOutcome ScoreStop(const World& world, std::string_view target_label,
                      const Eigen::Vector2d& final_position, bool stop_issued,
                      double success_radius) {
  StopOutcome outcome;
  outcome.distance_to_goal_m = DistanceToNearestInstance(world, target_label, final_position);
  outcome.success = stop_issued && outcome.distance_to_goal_m <= success_radius;
  return outcome;
}

double SuccessWeightedPathLength(bool success, double shortest_m, double path_m) {
  const double denominator = std::max(path_m, shortest_m);
  if (!success || denominator <= 0.0) return 0.0;
  return shortest_m / denominator;
}

std::vector<StrategySummary> SummariseByStrategy(const std::vector<EpisodeRecord>& records) {
  std::vector<StrategySummary> summaries;
  std::vector<int> resolved, fast;
  for (const EpisodeRecord& r : records) {
    auto it = std::find_if(summaries.begin(), summaries.end(),
                           [&](const StrategySummary& s) { return s.strategy == r.strategy; });
    if (it == summaries.end()) {
      summaries.emplace_back();
      summaries.back().strategy = r.strategy;
      resolved.push_back(0);
      fast.push_back(0);
      it = summaries.end() - 1;
    }
    const size_t k = it - summaries.begin();
    it->episodes += 1;
    it->sr += r.success ? 1.0 : 0.0;
    it->spl += SuccessWeightedPathLength(r.success, r.shortest_path_m, r.path_m);
    it->dtg_m += r.distance_to_goal_m;
    it->path_m += r.path_m;
    it->time_s += r.time_s;
    it->energy_j += r.energy_j;
    it->model_calls += r.model_calls;
    resolved[k] += r.goals_resolved;
    fast[k] += r.goals_fast_path;
  }
  for (size_t k = 0; k < summaries.size(); ++k) {
    StrategySummary& s = summaries[k];
    const double n = s.episodes;
    for (double* mean :
         {&s.sr, &s.spl, &s.dtg_m, &s.path_m, &s.time_s, &s.energy_j, &s.model_calls}) {
      *mean /= n;
    }
    s.fast_path_share = resolved[k] > 0 ? static_cast<double>(fast[k]) / resolved[k] : 0.0;
  }
  return summaries;
}

std::string ReportGroup(Modality modality) {
  switch (modality) {
    case Modality::kGround: return "indoor";
    case Modality::kUav: return "outdoor";
    case Modality::kFlyRoll: return "flyroll";
  }
  return "indoor";
}

}  // namespace semnav::sim
