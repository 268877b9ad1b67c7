#include "clients/sim/worlds/flyroll_scenes.h"

#include <cmath>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/worlds/scene_parts.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {

World FlyRollScene(const std::string& name, uint64_t seed) {
  Rng rng(seed);
  constexpr double kWidth = 20.0, kDepth = 16.0, kHeight = 4.5;
  World world;
  world.name = name;
  world.description = absl::StrCat("fly-roll hall, obstacles 1-4 m, seed ", seed);
  world.bounds_min = Eigen::Vector2d(-0.5, -0.5);
  world.bounds_max = Eigen::Vector2d(kWidth + 0.5, kDepth + 0.5);
  world.ceiling_height = kHeight;
  const Rgb wall{220, 220, 215};
  world.obstacles.push_back(
      Obstacle{"wall", wall, parts::Box(kWidth / 2, 0, kWidth + 0.1, 0.1, kHeight)});
  world.obstacles.push_back(
      Obstacle{"wall", wall, parts::Box(kWidth / 2, kDepth, kWidth + 0.1, 0.1, kHeight)});
  world.obstacles.push_back(
      Obstacle{"wall", wall, parts::Box(0, kDepth / 2, 0.1, kDepth + 0.1, kHeight)});
  world.obstacles.push_back(
      Obstacle{"wall", wall, parts::Box(kWidth, kDepth / 2, 0.1, kDepth + 0.1, kHeight)});
  for (int i = 0; i < 28; ++i) {
    for (int attempt = 0; attempt < 30; ++attempt) {
      // One draw per statement: argument evaluation order is unspecified in C++.
      const double h = rng.Uniform(1.0, 4.0);
      const double x = rng.Uniform(1.5, kWidth - 1.5);
      const double y = rng.Uniform(1.5, kDepth - 1.5);
      const double length = rng.Uniform(0.6, 2.5);
      const double width = rng.Uniform(0.6, 2.5);
      const double yaw = rng.UniformInt(0, 1) * std::acos(0.0);
      const BoxShape box = parts::Box(x, y, length, width, h, yaw);
      if (!parts::FreeSpot(world, box, 1.0)) continue;
      const uint8_t shade = static_cast<uint8_t>(90 + 30 * h);
      world.obstacles.push_back(Obstacle{"crate", Rgb{shade, 110, 80}, box});
      break;
    }
  }
  const std::vector<std::pair<std::string, Eigen::Vector3d>> items = {
      {"backpack", {0.35, 0.25, 0.5}},  {"suitcase", {0.5, 0.3, 0.7}},
      {"chair", {0.5, 0.5, 0.9}},       {"potted plant", {0.45, 0.45, 1.0}},
      {"teddy bear", {0.35, 0.3, 0.4}}, {"fire extinguisher", {0.2, 0.2, 0.6}}};
  for (const auto& [label, size] : items) {
    for (int attempt = 0; attempt < 60; ++attempt) {
      const double x = rng.Uniform(1, kWidth - 1);
      const double y = rng.Uniform(1, kDepth - 1);
      const double yaw = rng.Uniform(0, 3);
      const BoxShape box = parts::Box(x, y, size.x(), size.y(), size.z(), yaw);
      if (!parts::FreeSpot(world, box, 0.8)) continue;
      parts::AddObject(world, label, Rgb{static_cast<uint8_t>(rng.UniformInt(60, 230)), 60, 160},
                       box);
      break;
    }
  }
  RemoveUnreachableObjects(world, Modality::kFlyRoll, 0.0);
  world.starts = ChooseStarts(world, Modality::kFlyRoll, 0.0, 5, rng);
  return world;
}

}  // namespace semnav::sim
