#include "clients/sim/worlds/indoor_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/worlds/furnish.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

struct Rect {
  double x0, y0, x1, y1;
  double w() const { return x1 - x0; }
  double h() const { return y1 - y0; }
};

struct Split {
  bool vertical;  // wall along y at x = at
  double at;
  std::vector<int> low, high;  // leaf rooms on each side
};

constexpr double kMinSide = 2.6;

// Recursively splits `r` until rooms are at most `max_area`; returns leaf indices.
std::vector<int> Partition(const Rect& r, double max_area, Rng& rng, std::vector<Rect>& leaves,
                           std::vector<Split>& splits) {
  const bool vertical = r.w() >= r.h();
  const double side = vertical ? r.w() : r.h();
  if (r.w() * r.h() <= max_area || side < 2 * kMinSide) {
    leaves.push_back(r);
    return {static_cast<int>(leaves.size()) - 1};
  }
  const double lo = std::max(kMinSide, 0.35 * side), hi = std::min(side - kMinSide, 0.65 * side);
  const double cut = rng.Uniform(lo, hi);
  Rect a = r, b = r;
  Split split{vertical, 0.0, {}, {}};
  if (vertical) {
    split.at = a.x1 = b.x0 = r.x0 + cut;
  } else {
    split.at = a.y1 = b.y0 = r.y0 + cut;
  }
  const size_t index = splits.size();
  splits.push_back(split);
  std::vector<int> low = Partition(a, max_area, rng, leaves, splits);
  std::vector<int> high = Partition(b, max_area, rng, leaves, splits);
  splits[index].low = low;
  splits[index].high = high;
  low.insert(low.end(), high.begin(), high.end());
  return low;
}

Polygon2 RectPolygon(const Rect& r) {
  return {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}};
}

Obstacle WallSegment(Eigen::Vector2d a, Eigen::Vector2d b, const IndoorOptions& o) {
  BoxShape box;
  box.center = (a + b) / 2;
  const Eigen::Vector2d d = b - a;
  box.yaw = std::atan2(d.y(), d.x());
  // Extended by half a thickness each way so corners close.
  box.size = Eigen::Vector3d(d.norm() + o.wall_thickness, o.wall_thickness, o.wall_height);
  return Obstacle{"wall", Rgb{225, 220, 210}, box};
}

// Door interval along a split wall: centre of the overlap of two rooms facing each other.
std::optional<double> DoorCentre(const Split& s, const std::vector<Rect>& leaves,
                                 const IndoorOptions& o, Rng& rng) {
  std::vector<std::pair<double, double>> candidates;
  for (int a : s.low) {
    for (int b : s.high) {
      const Rect& ra = leaves[a];
      const Rect& rb = leaves[b];
      const bool touch = s.vertical
                             ? std::abs(ra.x1 - s.at) < 1e-9 && std::abs(rb.x0 - s.at) < 1e-9
                             : std::abs(ra.y1 - s.at) < 1e-9 && std::abs(rb.y0 - s.at) < 1e-9;
      if (!touch) continue;
      const double lo = s.vertical ? std::max(ra.y0, rb.y0) : std::max(ra.x0, rb.x0);
      const double hi = s.vertical ? std::min(ra.y1, rb.y1) : std::min(ra.x1, rb.x1);
      const double margin = o.door_width / 2 + 0.3;
      if (hi - lo >= 2 * margin) candidates.emplace_back(lo + margin, hi - margin);
    }
  }
  if (candidates.empty()) return std::nullopt;
  const auto [lo, hi] = candidates[rng.UniformInt(0, static_cast<int>(candidates.size()) - 1)];
  return rng.Uniform(lo, hi);
}

std::vector<std::string> RoomTypes(Building building, size_t count, Rng& rng) {
  // Ordered by decreasing room size.
  std::vector<std::string> types =
      building == Building::kHome
          ? std::vector<std::string>{"living_room", "kitchen", "bedroom", "dining_room",
                                     "bedroom",     "study",   "bathroom"}
          : std::vector<std::string>{"meeting_room", "office", "office",  "pantry",
                                     "office",       "office", "restroom"};
  std::vector<std::string> out;
  for (size_t i = 0; i < count; ++i) {
    if (i + 1 == count && count > 2) {
      out.push_back(types.back());  // the smallest room is the bathroom / restroom
    } else if (i < types.size() - 1) {
      out.push_back(types[i]);
    } else {
      out.push_back(types[1 + rng.UniformInt(0, static_cast<int>(types.size()) - 3)]);
    }
  }
  return out;
}

}  // namespace

World GenerateIndoor(const std::string& name, const IndoorOptions& options, uint64_t seed) {
  Rng rng(seed);
  const bool home = options.building == Building::kHome;
  const double width = home ? rng.Uniform(10, 14) : rng.Uniform(14, 20);
  const double depth = home ? rng.Uniform(8, 11) : rng.Uniform(10, 14);
  World world;
  world.name = name;
  world.description = absl::StrCat(home ? "generated home" : "generated office", ", seed ", seed);
  world.bounds_min = Eigen::Vector2d(-0.5, -0.5);
  world.bounds_max = Eigen::Vector2d(width + 0.5, depth + 0.5);
  world.ceiling_height = options.wall_height;
  world.floor_colour = home ? Rgb{170, 140, 110} : Rgb{150, 150, 155};
  std::vector<Rect> leaves;
  std::vector<Split> splits;
  Partition(Rect{0, 0, width, depth}, home ? 22.0 : 30.0, rng, leaves, splits);
  // Exterior walls.
  const Polygon2 outline = RectPolygon(Rect{0, 0, width, depth});
  for (size_t i = 0; i < 4; ++i) {
    world.obstacles.push_back(WallSegment(outline[i], outline[(i + 1) % 4], options));
  }
  // Interior walls with one door each, cut around the door opening.
  std::vector<Eigen::Vector2d> doors;
  for (const Split& s : splits) {
    const Rect span = [&] {
      Rect r{1e9, 1e9, -1e9, -1e9};
      for (const auto* side : {&s.low, &s.high}) {
        for (int l : *side) {
          r = Rect{std::min(r.x0, leaves[l].x0), std::min(r.y0, leaves[l].y0),
                   std::max(r.x1, leaves[l].x1), std::max(r.y1, leaves[l].y1)};
        }
      }
      return r;
    }();
    const double lo = s.vertical ? span.y0 : span.x0, hi = s.vertical ? span.y1 : span.x1;
    auto point = [&](double t) {
      return s.vertical ? Eigen::Vector2d(s.at, t) : Eigen::Vector2d(t, s.at);
    };
    const std::optional<double> door = DoorCentre(s, leaves, options, rng);
    if (!door) {
      world.obstacles.push_back(WallSegment(point(lo), point(hi), options));
      continue;
    }
    const double half = options.door_width / 2 + options.wall_thickness / 2;
    world.obstacles.push_back(WallSegment(point(lo), point(*door - half), options));
    world.obstacles.push_back(WallSegment(point(*door + half), point(hi), options));
    doors.push_back(point(*door));
  }
  // Rooms, largest first, typed and furnished.
  std::vector<int> order(leaves.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return leaves[a].w() * leaves[a].h() > leaves[b].w() * leaves[b].h();
  });
  const std::vector<std::string> types = RoomTypes(options.building, order.size(), rng);
  FurnishOptions furnish;
  furnish.doors = doors;
  for (size_t k = 0; k < order.size(); ++k) {
    Room room{absl::StrCat(types[k], "_", k + 1), types[k], RectPolygon(leaves[order[k]])};
    FurnishRoom(room, furnish, rng, &world);
    world.rooms.push_back(std::move(room));
  }
  RemoveUnreachableObjects(world, Modality::kGround, 0.0);
  world.starts = ChooseStarts(world, Modality::kGround, 0.0, options.starts, rng);
  return world;
}

}  // namespace semnav::sim
