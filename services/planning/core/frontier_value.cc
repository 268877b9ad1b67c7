#include "services/planning/core/frontier_value.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numeric>

namespace semnav::planning {
namespace {

double Evidence(Point2 centroid, const std::vector<ScoredObject>& objects, double sigma_m) {
  double best = 0.0;
  for (const ScoredObject& o : objects) {
    const double w = std::max({o.relevance, o.relation, o.cooccurrence});
    if (w <= 0.0) continue;
    const double d2 = (centroid.x - o.position.x) * (centroid.x - o.position.x) +
                      (centroid.y - o.position.y) * (centroid.y - o.position.y);
    best = std::max(best, std::clamp(w, 0.0, 1.0) * std::exp(-d2 / (2.0 * sigma_m * sigma_m)));
  }
  return best;
}

// Unexplored cells reachable from the frontier's unexplored 4-neighbours through unexplored
// cells, within radius_cells of the centroid. `stamp` marks cells of this frontier's count.
int UnexploredReach(const Frontier& frontier, const CellGrid<uint8_t>& explored,
                    double radius_cells, int mark, std::vector<int>& stamp) {
  const double cx = frontier.centroid_x;
  const double cy = frontier.centroid_y;
  const double r2 = radius_cells * radius_cells;
  std::deque<Cell> queue;
  auto visit = [&](int x, int y) {
    if (!explored.Contains(x, y) || explored.at(x, y) != 0) return;
    const int index = explored.Index(x, y);
    if (stamp[index] == mark) return;
    if ((x - cx) * (x - cx) + (y - cy) * (y - cy) > r2) return;
    stamp[index] = mark;
    queue.push_back({x, y});
  };
  constexpr int kDx[4] = {1, -1, 0, 0};
  constexpr int kDy[4] = {0, 0, 1, -1};
  for (const Cell& c : frontier.cells) {
    for (int m = 0; m < 4; ++m) visit(c.x + kDx[m], c.y + kDy[m]);
  }
  int count = 0;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    ++count;
    for (int m = 0; m < 4; ++m) visit(c.x + kDx[m], c.y + kDy[m]);
  }
  return count;
}

// Single-linkage clusters of the centroids within link_m; returns each frontier's region.
std::vector<int> Regions(const std::vector<FrontierCandidate>& candidates, double link_m) {
  std::vector<int> parent(candidates.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (size_t i = 0; i < candidates.size(); ++i) {
    for (size_t j = i + 1; j < candidates.size(); ++j) {
      const double d = std::hypot(candidates[i].centroid.x - candidates[j].centroid.x,
                                  candidates[i].centroid.y - candidates[j].centroid.y);
      if (d <= link_m) parent[find(static_cast<int>(j))] = find(static_cast<int>(i));
    }
  }
  std::vector<int> region(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) region[i] = find(static_cast<int>(i));
  return region;
}

}  // namespace

std::vector<FrontierValue> ValueFrontiers(const std::vector<Frontier>& frontiers,
                                          const std::vector<FrontierCandidate>& candidates,
                                          const CellGrid<uint8_t>& explored, double resolution_m,
                                          const std::vector<ScoredObject>& objects,
                                          const FrontierValueConfig& config) {
  std::vector<FrontierValue> values(frontiers.size());
  std::vector<int> stamp(explored.size(), -1);
  const std::vector<int> region = Regions(candidates, config.region_link_m);
  const double cell_area = resolution_m * resolution_m;
  for (size_t i = 0; i < frontiers.size(); ++i) {
    FrontierValue& v = values[i];
    v.region = region[i];
    v.evidence = Evidence(candidates[i].centroid, objects, config.evidence_sigma_m);
    v.gain_m2 = UnexploredReach(frontiers[i], explored, config.gain_radius_m / resolution_m,
                                static_cast<int>(i), stamp) *
                cell_area;
    if (candidates[i].path_distance_m < 0.0) continue;
    v.utility = (1.0 + config.semantic_gain * v.evidence) * v.gain_m2 *
                std::exp(-config.distance_decay_per_m * candidates[i].path_distance_m);
  }
  return values;
}

std::optional<int> SelectValuedFrontier(const std::vector<FrontierCandidate>& candidates,
                                        const std::vector<FrontierValue>& values,
                                        const FrontierValueConfig& config) {
  // Pockets below min_gain_m2 only when nothing else is reachable.
  bool any_worth = false;
  for (size_t i = 0; i < values.size(); ++i) {
    any_worth |= candidates[i].path_distance_m >= 0.0 && values[i].gain_m2 >= config.min_gain_m2;
  }
  auto eligible = [&](size_t i) {
    return candidates[i].path_distance_m >= 0.0 &&
           (!any_worth || values[i].gain_m2 >= config.min_gain_m2);
  };
  struct RegionTotals {
    double evidence = 0.0, gain = 0.0, distance = -1.0;
  };
  std::vector<RegionTotals> regions(values.size());
  for (size_t i = 0; i < values.size(); ++i) {
    if (!eligible(i)) continue;
    RegionTotals& r = regions[values[i].region];
    r.evidence = std::max(r.evidence, values[i].evidence);
    r.gain = std::max(r.gain, values[i].gain_m2);
    const double d = candidates[i].path_distance_m;
    r.distance = r.distance < 0.0 ? d : std::min(r.distance, d);
  }
  int best_region = -1;
  double best_region_utility = -1.0;
  for (size_t r = 0; r < regions.size(); ++r) {
    if (regions[r].distance < 0.0) continue;
    const double u = (1.0 + config.semantic_gain * regions[r].evidence) * regions[r].gain *
                     std::exp(-config.distance_decay_per_m * regions[r].distance);
    if (u > best_region_utility) {
      best_region_utility = u;
      best_region = static_cast<int>(r);
    }
  }
  if (best_region < 0) return std::nullopt;
  std::optional<int> best;
  for (size_t i = 0; i < values.size(); ++i) {
    if (!eligible(i) || values[i].region != best_region) continue;
    // Ties (e.g. no gain anywhere): the nearer one.
    if (!best || values[i].utility > values[*best].utility ||
        (values[i].utility == values[*best].utility &&
         candidates[i].path_distance_m < candidates[*best].path_distance_m)) {
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace semnav::planning
