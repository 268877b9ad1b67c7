#include "clients/sim/worlds/houseexpo_world.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/worlds/furnish.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

constexpr double kWallHeight = 2.6, kWallThickness = 0.1;

std::string RoomType(const std::string& category) {
  if (category == "Toilet") return "bathroom";
  std::string type = category;
  std::transform(type.begin(), type.end(), type.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return type;
}

absl::Status Invalid(absl::string_view key, absl::string_view what) {
  return absl::InvalidArgumentError(absl::StrCat("houseexpo.", key, ": ", what));
}

// Outline edges as walls just outside the free space (outward = right of a CCW edge).
void AddWalls(const Polygon2& outline, World& world) {
  double twice_area = 0.0;
  for (size_t i = 0, j = outline.size() - 1; i < outline.size(); j = i++) {
    twice_area += outline[j].x() * outline[i].y() - outline[i].x() * outline[j].y();
  }
  const double outward = twice_area > 0 ? 1.0 : -1.0;
  for (size_t i = 0; i < outline.size(); ++i) {
    const Eigen::Vector2d a = outline[i], b = outline[(i + 1) % outline.size()];
    const Eigen::Vector2d d = b - a;
    const double length = d.norm();
    if (length < 1e-6) continue;
    const Eigen::Vector2d normal = outward * Eigen::Vector2d(d.y(), -d.x()) / length;
    BoxShape box;
    box.center = (a + b) / 2 + normal * kWallThickness / 2;
    box.yaw = std::atan2(d.y(), d.x());
    box.size = Eigen::Vector3d(length + kWallThickness, kWallThickness, kWallHeight);
    world.obstacles.push_back(Obstacle{"wall", Rgb{225, 220, 210}, box});
  }
}

}  // namespace

absl::StatusOr<World> HouseExpoWorld(const std::string& json_path, const std::string& name,
                                     uint64_t seed) {
  std::ifstream in(json_path);
  if (!in) return absl::NotFoundError(absl::StrCat("HouseExpo file not readable: ", json_path));
  const nlohmann::json plan = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (plan.is_discarded() || !plan.is_object()) return Invalid("", "not a JSON object");
  if (!plan.contains("verts") || !plan["verts"].is_array() || plan["verts"].size() < 3) {
    return Invalid("verts", "expected at least 3 [x, y] points");
  }
  Polygon2 outline;
  for (const auto& v : plan["verts"]) {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
      return Invalid("verts", "expected [x, y] number pairs");
    }
    outline.emplace_back(v[0].get<double>(), v[1].get<double>());
  }
  World world;
  world.name = name;
  world.description = absl::StrCat("HouseExpo plan ", plan.value("id", std::string("?")),
                                   " furnished with seed ", seed);
  const auto [lo, hi] = FootprintBounds(PrismShape{outline, 0.0, 1.0});
  // Tight bounds: the thin ring outside the walls is fully inflated away, so the largest
  // free region (where starts go) is the home itself.
  world.bounds_min = lo - Eigen::Vector2d(0.15, 0.15);
  world.bounds_max = hi + Eigen::Vector2d(0.15, 0.15);
  world.ceiling_height = kWallHeight;
  world.floor_colour = Rgb{170, 140, 110};
  AddWalls(outline, world);
  if (!plan.contains("room_category") || !plan["room_category"].is_object()) {
    return Invalid("room_category", "expected an object of category -> boxes");
  }
  std::vector<std::array<double, 4>> seen;
  for (const auto& [category, boxes] : plan["room_category"].items()) {
    if (!boxes.is_array())
      return Invalid(absl::StrCat("room_category.", category), "expected boxes");
    for (const auto& b : boxes) {
      if (!b.is_array() || b.size() != 4) {
        return Invalid(absl::StrCat("room_category.", category), "expected [x1, y1, x2, y2]");
      }
      // Room boxes overlap the walls: clip them to the outline's bounds.
      const std::array<double, 4> r = {
          std::max(b[0].get<double>(), lo.x()), std::max(b[1].get<double>(), lo.y()),
          std::min(b[2].get<double>(), hi.x()), std::min(b[3].get<double>(), hi.y())};
      if (std::find(seen.begin(), seen.end(), r) != seen.end()) continue;
      seen.push_back(r);
      const std::string type = RoomType(category);
      world.rooms.push_back(Room{absl::StrCat(type, "_", world.rooms.size() + 1),
                                 type,
                                 {{r[0], r[1]}, {r[2], r[1]}, {r[2], r[3]}, {r[0], r[3]}}});
    }
  }
  Rng rng(seed);
  FurnishOptions furnish;
  furnish.outline = &outline;
  for (const Room& room : world.rooms) FurnishRoom(room, furnish, rng, &world);
  RemoveUnreachableObjects(world, Modality::kGround, 0.0);
  world.starts = ChooseStarts(world, Modality::kGround, 0.0, 5, rng);
  return world;
}

}  // namespace semnav::sim
