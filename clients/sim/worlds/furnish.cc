#include "clients/sim/worlds/furnish.h"

#include <cmath>
#include <numbers>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "clients/sim/worlds/room_object_table.h"

namespace semnav::sim {
namespace {

struct Placed {
  std::string label;
  BoxShape box;
};

// Inside `polygon` with no polygon vertex poking into the footprint (catches the thin
// wall slits of HouseExpo outlines and concave corners).
bool FitsInside(const BoxShape& box, const Polygon2& polygon) {
  for (const auto& corner : BoxCorners(box)) {
    if (!PointInPolygon(polygon, corner)) return false;
  }
  for (const auto& vertex : polygon) {
    if (DistanceToBoxFootprint(box, vertex) < 0.02) return false;
  }
  return true;
}

bool FloorFree(const BoxShape& box, const World& world, double clearance) {
  for (const ObjectInstance& o : world.objects) {
    if (o.box.base_z < 0.1 && FootprintsOverlap(box, o.box, clearance)) return false;
  }
  for (const Obstacle& o : world.obstacles) {
    const auto* other = std::get_if<BoxShape>(&o.shape);
    if (other != nullptr && o.kind != "wall" && other->base_z < 0.1 &&
        FootprintsOverlap(box, *other, clearance)) {
      return false;
    }
  }
  return true;
}

// Signed area > 0 for counter-clockwise polygons.
double SignedArea(const Polygon2& p) {
  double twice = 0.0;
  for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    twice += p[j].x() * p[i].y() - p[i].x() * p[j].y();
  }
  return twice / 2.0;
}

std::optional<BoxShape> AgainstWall(const ItemSpec& item, const Room& room,
                                    const FurnishOptions& options, Rng& rng) {
  const Polygon2& poly = room.polygon;
  const double inward = SignedArea(poly) > 0 ? 1.0 : -1.0;
  const size_t i = static_cast<size_t>(rng.UniformInt(0, static_cast<int>(poly.size()) - 1));
  const Eigen::Vector2d a = poly[i], b = poly[(i + 1) % poly.size()];
  const double length = (b - a).norm();
  if (length < item.size.x() + 0.2) return std::nullopt;
  const Eigen::Vector2d e = (b - a) / length;
  const Eigen::Vector2d normal = inward * Eigen::Vector2d(-e.y(), e.x());
  const double along = rng.Uniform(item.size.x() / 2 + 0.1, length - item.size.x() / 2 - 0.1);
  BoxShape box;
  box.center = a + e * along + normal * (item.size.y() / 2 + options.wall_gap);
  box.yaw = std::atan2(e.y(), e.x());
  box.size = item.size;
  return box;
}

std::optional<BoxShape> FreeStanding(const ItemSpec& item, const Room& room, Rng& rng) {
  const auto [lo, hi] = FootprintBounds(PrismShape{room.polygon, 0.0, 1.0});
  BoxShape box;
  // One draw per statement: argument evaluation order is unspecified in C++.
  box.center.x() = rng.Uniform(lo.x(), hi.x());
  box.center.y() = rng.Uniform(lo.y(), hi.y());
  box.yaw = rng.UniformInt(0, 3) * std::numbers::pi / 2;
  box.yaw += rng.Uniform(-0.2, 0.2);
  box.size = item.size;
  return box;
}

std::optional<BoxShape> OnTop(const ItemSpec& item, const std::vector<Placed>& placed, Rng& rng) {
  std::vector<const Placed*> supports;
  for (const Placed& p : placed) {
    if (p.label == item.on) supports.push_back(&p);
  }
  if (supports.empty()) return std::nullopt;
  const BoxShape& parent = supports[rng.UniformInt(0, static_cast<int>(supports.size()) - 1)]->box;
  const double sx = std::max(0.0, (parent.size.x() - item.size.x()) / 2);
  const double sy = std::max(0.0, (parent.size.y() - item.size.y()) / 2);
  Eigen::Vector2d local;
  local.x() = rng.Uniform(-sx, sx);
  local.y() = rng.Uniform(-sy, sy);
  const double c = std::cos(parent.yaw), s = std::sin(parent.yaw);
  BoxShape box;
  box.center =
      parent.center + Eigen::Vector2d(c * local.x() - s * local.y(), s * local.x() + c * local.y());
  box.yaw = parent.yaw;
  box.size = item.size;
  box.base_z = parent.top_z();
  return box;
}

bool Acceptable(const BoxShape& box, const ItemSpec& item, const Room& room,
                const FurnishOptions& options, const World& world) {
  if (item.placement == Placement::kOnTop) return true;  // the support was already checked
  const bool free = item.placement == Placement::kFree;
  BoxShape grown = box;
  if (free) grown.size += Eigen::Vector3d(2 * options.aisle, 2 * options.aisle, 0);
  if (!FitsInside(grown, room.polygon)) return false;
  if (options.outline != nullptr && !FitsInside(grown, *options.outline)) return false;
  for (const auto& door : options.doors) {
    if (DistanceToBoxFootprint(box, door) < options.door_clearance) return false;
  }
  return FloorFree(box, world, free ? options.aisle / 2 : 0.02);
}

std::string NextId(const World& world, const std::string& label) {
  const std::string stem = absl::StrReplaceAll(label, {{" ", "_"}});
  int n = 1;
  for (const ObjectInstance& o : world.objects) n += o.label == label ? 1 : 0;
  return absl::StrCat(stem, "_", n);
}

}  // namespace

void FurnishRoom(const Room& room, const FurnishOptions& options, Rng& rng, World* world) {
  std::vector<Placed> placed;
  for (const ItemSpec& item : RoomItems(room.type)) {
    const int count = rng.UniformInt(item.min_count, item.max_count);
    for (int k = 0; k < count; ++k) {
      for (int attempt = 0; attempt < options.tries; ++attempt) {
        std::optional<BoxShape> box;
        switch (item.placement) {
          case Placement::kAgainstWall:
            box = AgainstWall(item, room, options, rng);
            break;
          case Placement::kFree:
            box = FreeStanding(item, room, rng);
            break;
          case Placement::kOnTop:
            box = OnTop(item, placed, rng);
            break;
        }
        if (!box || !Acceptable(*box, item, room, options, *world)) continue;
        placed.push_back({item.label, *box});
        if (item.findable) {
          world->objects.push_back(
              ObjectInstance{NextId(*world, item.label), item.label, item.colour, *box, room.name});
        } else {
          world->obstacles.push_back(Obstacle{"furniture", item.colour, *box});
        }
        break;
      }
    }
  }
}

}  // namespace semnav::sim
