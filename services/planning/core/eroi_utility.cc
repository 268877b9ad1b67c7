#include "services/planning/core/eroi_utility.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <queue>

#include "services/planning/core/alternative_point.h"
#include "services/planning/core/distance_field.h"

namespace semnav::planning {
namespace {

struct Node {
  Cell cell;
  int eroi = -1;  // -1 for the robot
  double gain = 0.0;
};

bool SegmentFree(const PassabilityGrid& free, Cell a, Cell b) {
  for (const Cell& c : LineCells(a, b)) {
    if (!IsFree(free, c.x, c.y)) return false;
  }
  return true;
}

// An EROI is active once some of it is explored, and still worth a look
// while some of it is not.
bool Active(const ExplorationLayers& layers, int x0, int y0, int size) {
  bool seen = false;
  bool unseen = false;
  for (int y = y0; y < std::min(y0 + size, layers.explored.height()); ++y) {
    for (int x = x0; x < std::min(x0 + size, layers.explored.width()); ++x) {
      (layers.explored.at(x, y) != 0 ? seen : unseen) = true;
    }
  }
  return seen && unseen;
}

}  // namespace

int EroiCount(int width, int height, const EroiConfig& config) {
  const int d = config.eroi_size_cells;
  return ((width + d - 1) / d) * ((height + d - 1) / d);
}

int ViewpointGain(const ExplorationLayers& layers, Cell viewpoint, const EroiConfig& config) {
  std::vector<uint8_t> counted(layers.explored.size(), 0);
  int gain = 0;
  for (int r = 0; r < config.rays; ++r) {
    const double angle = 2 * std::numbers::pi * r / config.rays;
    const Cell end{
        static_cast<int>(std::lround(viewpoint.x + config.ray_range_cells * std::cos(angle))),
        static_cast<int>(std::lround(viewpoint.y + config.ray_range_cells * std::sin(angle)))};
    for (const Cell& c : LineCells(viewpoint, end)) {
      if (!layers.explored.Contains(c)) break;
      const int i = layers.explored.Index(c);
      if (layers.explored.values()[i] != 0) {
        if (layers.free.values()[i] == 0) break;  // the ray ends on an obstacle
        continue;
      }
      if (counted[i] == 0) {
        counted[i] = 1;
        ++gain;
      }
    }
  }
  return gain;
}

std::optional<EroiChoice> SelectEroiGoal(const ExplorationLayers& layers, Cell robot,
                                         const std::vector<double>& semantic,
                                         const EroiConfig& config,
                                         const std::function<bool(Cell)>& excluded) {
  const int d = config.eroi_size_cells;
  const int columns = (layers.explored.width() + d - 1) / d;
  const int count = EroiCount(layers.explored.width(), layers.explored.height(), config);
  const auto s = [&](int eroi) { return semantic.empty() ? 1.0 / count : semantic[eroi]; };

  std::vector<Node> nodes = {{robot, -1, 0.0}};
  for (int e = 0; e < count; ++e) {
    const int x0 = (e % columns) * d;
    const int y0 = (e / columns) * d;
    if (!Active(layers, x0, y0, d)) continue;
    for (int v = 0; v < config.viewpoints_per_eroi; ++v) {
      const double angle = 2 * std::numbers::pi * v / config.viewpoints_per_eroi;
      const Cell c{static_cast<int>(
                       std::lround(x0 + d / 2.0 + config.viewpoint_radius_cells * std::cos(angle))),
                   static_cast<int>(std::lround(y0 + d / 2.0 +
                                                config.viewpoint_radius_cells * std::sin(angle)))};
      if (!IsFree(layers.free, c.x, c.y) || layers.explored.at(c) == 0) continue;
      if (excluded && excluded(c)) continue;
      const int gain = ViewpointGain(layers, c, config);
      // Specks of unknown (depth noise, a corner behind a post) are not worth a flight: with a
      // clue's value 100 times the prior, a clue EROI's last few unknown cells outweighed whole
      // unexplored areas, and the UAV flew back and forth between clue EROIs.
      if (gain > 0 && gain >= config.min_gain_cells) {
        nodes.push_back({c, e, static_cast<double>(gain)});
      }
    }
  }
  double s_max = 0.0;
  for (const Node& n : nodes) {
    if (n.eroi >= 0) s_max = std::max(s_max, s(n.eroi));
  }
  const double tau = config.k * s_max;
  // The greedy branch of eq. 24 is for "high-confidence clues" (seed 000, 2.2.3): a value above
  // the floor eq. 23 keeps every EROI at. Without a clue (uniform values, the start of every
  // search) every s equals max s, so eq. 24 read literally dropped the path cost everywhere and
  // the UAV zig-zagged between the best gains across the area; now it pays the path cost there.
  const double s_floor =
      semantic.empty() ? s(0) : *std::min_element(semantic.begin(), semantic.end());
  const auto greedy = [&](int eroi) { return s(eroi) > tau && s(eroi) > s_floor; };

  // Dijkstra over the sparse roadmap (edges built on demand). The seed's roadmap is always
  // connected; straight edges up to the connect radius alone are not once the robot stands in
  // explored space wider than that radius (no active EROI near it: nothing reachable, and the
  // gateway fell back to blind 3 m steps). So the robot also reaches every viewpoint by its
  // octile path through explored free space, which straight roadmap edges may then shorten.
  std::vector<double> dist(nodes.size(), INFINITY);
  std::vector<int> parent(nodes.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[0] = 0.0;
  open.push({0.0, 0});
  if (layers.free.Contains(robot)) {
    const std::vector<double> field = OctileDistanceField(layers.free, robot);
    for (size_t j = 1; j < nodes.size(); ++j) {
      const double path = field[layers.free.Index(nodes[j].cell)];
      if (path == kUnreachable) continue;
      dist[j] = path;
      parent[j] = 0;
      open.push({path, static_cast<int>(j)});
    }
  }
  std::optional<EroiChoice> best;
  // The path to the nearest clue viewpoint (nodes leave the queue in path order). A clue ignores
  // its path length against the rest, as eq. 24 says; between clues, eq. 24 read literally chose
  // by I s alone, and as gains shrank under the camera the UAV flew from one end of a clue-lit
  // road to the other and back (20 m legs, outdoor_building_vehicles start 4, seed 2).
  std::optional<double> nearest_clue;
  while (!open.empty()) {
    const auto [l, i] = open.top();
    open.pop();
    if (l > dist[i]) continue;
    if (nodes[i].eroi >= 0) {
      const double value = nodes[i].gain * s(nodes[i].eroi);  // U_b = I s
      double paid_path = l;                                   // the path length U pays for
      if (greedy(nodes[i].eroi)) {
        if (!nearest_clue) nearest_clue = l;
        paid_path = config.clues_pay_extra_path ? l - *nearest_clue : 0.0;
      }
      const double u = value * std::exp(-config.lambda * paid_path);
      if (!best || u > best->utility) {
        best = EroiChoice{nodes[i].cell, nodes[i].eroi, nodes[i].gain, s(nodes[i].eroi), l, u, {}};
        for (int at = i; at >= 0; at = parent[at]) best->route.push_back(nodes[at].cell);
        std::reverse(best->route.begin(), best->route.end());
      }
    }
    for (size_t j = 1; j < nodes.size(); ++j) {
      const double edge =
          std::hypot(nodes[j].cell.x - nodes[i].cell.x, nodes[j].cell.y - nodes[i].cell.y);
      if (edge > config.connect_radius_cells || l + edge >= dist[j]) continue;
      if (!SegmentFree(layers.free, nodes[i].cell, nodes[j].cell)) continue;
      dist[j] = l + edge;
      parent[j] = static_cast<int>(i);
      open.push({dist[j], static_cast<int>(j)});
    }
  }
  return best;
}

}  // namespace semnav::planning
