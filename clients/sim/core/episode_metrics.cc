#include "clients/sim/core/episode_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <utility>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/shape_queries.h"

namespace semnav::sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The point of a box footprint nearest to `p` (p itself inside).
Eigen::Vector2d NearestFootprintPoint(const BoxShape& box, const Eigen::Vector2d& p) {
  const Eigen::Vector2d u(std::cos(box.yaw), std::sin(box.yaw));
  const Eigen::Vector2d v(-u.y(), u.x());
  const Eigen::Vector2d d = p - box.center;
  const double a = std::clamp(d.dot(u), -box.size.x() / 2.0, box.size.x() / 2.0);
  const double b = std::clamp(d.dot(v), -box.size.y() / 2.0, box.size.y() / 2.0);
  return box.center + a * u + b * v;
}

// True when the shape's footprint shares area with the box footprint.
bool FootprintTouches(const Shape& shape, const BoxShape& box) {
  if (const auto* other = std::get_if<BoxShape>(&shape)) return FootprintsOverlap(*other, box, 0.0);
  const Polygon2& polygon = std::get<PrismShape>(shape).polygon;
  if (PointInPolygon(polygon, box.center)) return true;
  for (const Eigen::Vector2d& corner : BoxCorners(box)) {
    if (PointInPolygon(polygon, corner)) return true;
  }
  for (const Eigen::Vector2d& vertex : polygon) {
    if (DistanceToBoxFootprint(box, vertex) == 0.0) return true;
  }
  return false;
}

// The solids that can hide `target` from a view cell: those reaching its mid-height within
// `reach` of its footprint, other than instances of its label and the non-structure solids
// it stands on or in.
std::vector<Shape> Blockers(const World& world, const ObjectInstance& target, double reach) {
  const double mid_z = target.box.base_z + target.box.size.z() / 2.0;
  // Plain locals, not a structured binding: clang 14 (the fuzz build) cannot capture one.
  const auto bounds = FootprintBounds(Shape(target.box));
  Eigen::Vector2d lo = bounds.first;
  Eigen::Vector2d hi = bounds.second;
  lo.array() -= reach;
  hi.array() += reach;
  std::vector<Shape> blockers;
  auto consider = [&](const Shape& shape, bool structure) {
    const Eigen::AlignedBox3d bounds = ShapeBounds(shape);
    if (bounds.min().z() > mid_z || bounds.max().z() < mid_z) return;
    if (bounds.min().x() > hi.x() || bounds.max().x() < lo.x() || bounds.min().y() > hi.y() ||
        bounds.max().y() < lo.y()) {
      return;
    }
    if (!structure && FootprintTouches(shape, target.box)) return;
    blockers.push_back(shape);
  };
  for (const Obstacle& o : world.obstacles) consider(o.shape, IsStructure(o.kind));
  for (const ObjectInstance& o : world.objects) {
    if (o.label != target.label) consider(Shape(o.box), false);
  }
  return blockers;
}

bool LineClear(const std::vector<Shape>& blockers, const Eigen::Vector2d& from,
               const Eigen::Vector2d& to, double z) {
  const Eigen::Vector2d delta = to - from;
  const double length = delta.norm();
  if (length < 1e-9) return true;
  const Eigen::Vector3d origin(from.x(), from.y(), z);
  const Eigen::Vector3d dir(delta.x() / length, delta.y() / length, 0.0);
  for (const Shape& shape : blockers) {
    if (IntersectRay(shape, origin, dir, 0.0, length - 1e-6).has_value()) return false;
  }
  return true;
}

// Straight distance from `from` to the nearest point of the box footprint seen from it at
// height z, infinity when none within `reach` is. The nearest point is tried first; when a
// solid hides it, points spread over the footprint (at most every 5 cm, 16 per side) are, since
// Habitat's view points need some of the object in view, not its nearest point (a laptop
// behind a monitor's corner is seen past the monitor's edge).
double VisibleFootprintDistance(const std::vector<Shape>& blockers, const BoxShape& box,
                                const Eigen::Vector2d& from, double z, double reach) {
  const Eigen::Vector2d nearest = NearestFootprintPoint(box, from);
  const double straight = (nearest - from).norm();
  if (straight > reach) return kInfinity;
  if (LineClear(blockers, from, nearest, z)) return straight;
  // Corners 0 -> 1 run along the box's x side, 0 -> 3 along its y side (BoxCorners).
  const std::array<Eigen::Vector2d, 4> corner = BoxCorners(box);
  const Eigen::Vector2d along_x = corner[1] - corner[0], along_y = corner[3] - corner[0];
  auto samples = [](double extent) {
    return std::clamp(static_cast<int>(std::ceil(extent / 0.05)) + 1, 2, 16);
  };
  const int nu = samples(box.size.x()), nv = samples(box.size.y());
  double best = kInfinity;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const Eigen::Vector2d point = corner[0] + i / (nu - 1.0) * along_x + j / (nv - 1.0) * along_y;
      const double distance = (point - from).norm();
      if (distance > reach || distance >= best) continue;
      if (LineClear(blockers, from, point, z)) best = distance;
    }
  }
  return best;
}

}  // namespace

double DistanceToNearestInstance(const World& world, std::string_view label,
                                 const Eigen::Vector2d& position) {
  double best = std::numeric_limits<double>::infinity();
  for (const ObjectInstance& object : world.objects) {
    if (object.label == label) best = std::min(best, DistanceToBoxFootprint(object.box, position));
  }
  return best;
}

SuccessRegion SuccessRegion::Build(const World& world, std::string_view label,
                                   const GroundTruthGrid& body_grid, double success_radius) {
  SuccessRegion region;
  region.geometry_ = body_grid;
  region.geometry_.cells.clear();
  region.radius_ = success_radius;
  const GroundTruthGrid& g = body_grid;
  const size_t cells = static_cast<size_t>(g.width) * g.height;
  region.free_.resize(cells);
  for (size_t i = 0; i < cells; ++i) region.free_[i] = g.cells[i] == 0 ? 1 : 0;
  region.distance_.assign(cells, static_cast<float>(kInfinity));
  std::vector<double> cost(cells, kInfinity);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  // View cells: free, with a clear straight line to a point of a footprint within the radius.
  for (const ObjectInstance& object : world.objects) {
    if (object.label != label) continue;
    const std::vector<Shape> blockers = Blockers(world, object, success_radius);
    const double mid_z = object.box.base_z + object.box.size.z() / 2.0;
    auto [lo, hi] = FootprintBounds(Shape(object.box));
    const int x0 = std::max(
        0, static_cast<int>(std::floor((lo.x() - success_radius - g.origin.x()) / g.resolution)));
    const int y0 = std::max(
        0, static_cast<int>(std::floor((lo.y() - success_radius - g.origin.y()) / g.resolution)));
    const int x1 = std::min(
        g.width - 1,
        static_cast<int>(std::floor((hi.x() + success_radius - g.origin.x()) / g.resolution)));
    const int y1 = std::min(
        g.height - 1,
        static_cast<int>(std::floor((hi.y() + success_radius - g.origin.y()) / g.resolution)));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const int index = y * g.width + x;
        if (!region.free_[index]) continue;
        const Eigen::Vector2d centre = g.CellCentre(x, y);
        if (DistanceToBoxFootprint(object.box, centre) >= cost[index]) continue;
        const double seen =
            VisibleFootprintDistance(blockers, object.box, centre, mid_z, success_radius);
        if (seen >= cost[index]) continue;
        cost[index] = seen;
        open.push({seen, index});
      }
    }
  }
  // Geodesic distance over the free cells, 8-connected with octile steps and no corner cutting
  // (as NearestReachableGoal), up to the radius.
  auto free = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < g.width && y < g.height &&
           region.free_[static_cast<size_t>(y) * g.width + x];
  };
  while (!open.empty()) {
    const auto [c, index] = open.top();
    open.pop();
    if (c > cost[index]) continue;
    region.distance_[index] = static_cast<float>(c);
    region.empty_ = false;
    const int x = index % g.width, y = index / g.width;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || !free(x + dx, y + dy)) continue;
        if (dx != 0 && dy != 0 && !(free(x + dx, y) && free(x, y + dy))) continue;
        const double next = c + g.resolution * (dx != 0 && dy != 0 ? std::sqrt(2.0) : 1.0);
        const int n = (y + dy) * g.width + x + dx;
        if (next <= success_radius && next < cost[n]) {
          cost[n] = next;
          open.push({next, n});
        }
      }
    }
  }
  return region;
}

double SuccessRegion::GeodesicDistance(const Eigen::Vector2d& p) const {
  const GroundTruthGrid& g = geometry_;
  const Eigen::Vector2d local = (p - g.origin) / g.resolution;
  const int cx = static_cast<int>(std::floor(local.x())),
            cy = static_cast<int>(std::floor(local.y()));
  if (cx >= 0 && cy >= 0 && cx < g.width && cy < g.height) {
    const size_t index = static_cast<size_t>(cy) * g.width + cx;
    if (free_[index]) return distance_[index] <= radius_ ? distance_[index] : kInfinity;
  }
  double best = kInfinity;
  for (int y = cy - 2; y <= cy + 2; ++y) {
    for (int x = cx - 2; x <= cx + 2; ++x) {
      if (x < 0 || y < 0 || x >= g.width || y >= g.height) continue;
      const size_t index = static_cast<size_t>(y) * g.width + x;
      if (free_[index]) best = std::min(best, distance_[index] + (g.CellCentre(x, y) - p).norm());
    }
  }
  return best <= radius_ ? best : kInfinity;
}

StopOutcome ScoreStop(const World& world, const SuccessRegion& region,
                      std::string_view target_label, const Eigen::Vector2d& final_position,
                      bool stop_issued) {
  StopOutcome outcome;
  outcome.distance_to_goal_m = DistanceToNearestInstance(world, target_label, final_position);
  outcome.success = stop_issued && region.Contains(final_position);
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
    it->model_tokens += static_cast<double>(r.model_tokens);
    it->model_wait_s += r.model_wait_s;
    it->vision_calls += r.vision_calls;
    resolved[k] += r.goals_resolved;
    fast[k] += r.goals_fast_path;
    if (!r.success) ++it->failures[r.failure_cause.empty() ? "unclassified" : r.failure_cause];
  }
  for (size_t k = 0; k < summaries.size(); ++k) {
    StrategySummary& s = summaries[k];
    const double n = s.episodes;
    for (double* mean : {&s.sr, &s.spl, &s.dtg_m, &s.path_m, &s.time_s, &s.energy_j, &s.model_calls,
                         &s.model_tokens, &s.model_wait_s, &s.vision_calls}) {
      *mean /= n;
    }
    s.fast_path_share = resolved[k] > 0 ? static_cast<double>(fast[k]) / resolved[k] : 0.0;
  }
  return summaries;
}

std::string ReportGroup(Modality modality) {
  switch (modality) {
    case Modality::kGround:
      return "indoor";
    case Modality::kUav:
      return "outdoor";
    case Modality::kFlyRoll:
      return "flyroll";
  }
  return "indoor";
}

}  // namespace semnav::sim
