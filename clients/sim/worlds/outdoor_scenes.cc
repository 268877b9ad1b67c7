#include "clients/sim/worlds/outdoor_scenes.h"

#include <algorithm>
#include <array>
#include <functional>
#include <numbers>

#include "clients/sim/core/rng.h"
#include "clients/sim/worlds/scene_parts.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

using parts::AddObject;
using parts::Box;

constexpr double kAltitude = 1.5;
constexpr Rgb kRoad{70, 70, 75}, kGrass{95, 150, 80}, kCar{180, 30, 30}, kCarBlue{40, 70, 160},
    kBin{40, 100, 60}, kBench{120, 80, 50}, kConcrete{180, 180, 175}, kWater{60, 110, 190};

World Base(const std::string& name, const std::string& description, double w, double h) {
  World world;
  world.name = name;
  world.description = description;
  world.bounds_min = Eigen::Vector2d(0, 0);
  world.bounds_max = Eigen::Vector2d(w, h);
  world.floor_colour = kGrass;
  return world;
}

// Scatters `count` boxes of a kind where they do not overlap anything (tries a few times).
void Scatter(World& world, Rng& rng, int count, const std::function<BoxShape(Rng&)>& make,
             const std::function<void(const BoxShape&)>& add, double gap) {
  for (int i = 0; i < count; ++i) {
    for (int attempt = 0; attempt < 40; ++attempt) {
      const BoxShape box = make(rng);
      if (parts::FreeSpot(world, box, gap)) {
        add(box);
        break;
      }
    }
  }
}

void ScatterTrees(World& world, Rng& rng, int count, double x0, double y0, double x1, double y1,
                  const std::vector<std::array<double, 4>>& avoid) {
  Scatter(
      world, rng, count,
      [&](Rng& r) {
        for (int k = 0;; ++k) {
          const double x = r.Uniform(x0, x1), y = r.Uniform(y0, y1);
          bool clear = true;
          for (const auto& a : avoid)
            clear =
                clear && !(x > a[0] - 1.5 && x < a[2] + 1.5 && y > a[1] - 1.5 && y < a[3] + 1.5);
          if (clear || k > 20) return Box(x, y, 2.4, 2.4, 1.0);
        }
      },
      [&](const BoxShape& b) {
        // The canopy (2.4 m, turned 0.3 rad) reaches 1.5 m from the trunk: keep it inside the
        // bounds, which the world loader checks (moves a tree by at most 0.5 m, same draws).
        constexpr double kCanopyReach = 1.51;
        const double x = std::clamp(b.center.x(), world.bounds_min.x() + kCanopyReach,
                                    world.bounds_max.x() - kCanopyReach);
        const double y = std::clamp(b.center.y(), world.bounds_min.y() + kCanopyReach,
                                    world.bounds_max.y() - kCanopyReach);
        parts::AddTree(world, x, y, rng.Uniform(3.5, 6.0));
      },
      1.0);
}

// `count` boxes of `size` at random spots of the area [x0, x1] x [y0, y1], turned at random
// when `turn`, kept `gap` from everything; `add` stores each one.
void ScatterBoxes(World& world, Rng& rng, int count, std::array<double, 4> area,
                  Eigen::Vector3d size, bool turn, double gap,
                  const std::function<void(const BoxShape&)>& add) {
  Scatter(
      world, rng, count,
      [&](Rng& r) {
        const double x = r.Uniform(area[0], area[2]), y = r.Uniform(area[1], area[3]);
        return Box(x, y, size.x(), size.y(), size.z(), turn ? r.Uniform(0, 3) : 0.0);
      },
      add, gap);
}

std::function<void(const BoxShape&)> AsObstacle(World& world, const char* kind, Rgb colour) {
  return [&world, kind, colour](const BoxShape& b) {
    world.obstacles.push_back(Obstacle{kind, colour, b});
  };
}

std::function<void(const BoxShape&)> AsObject(World& world, const char* label, Rgb colour) {
  return [&world, label, colour](const BoxShape& b) { AddObject(world, label, colour, b); };
}

void Finish(World& world, Rng& rng) {
  RemoveUnreachableObjects(world, Modality::kUav, kAltitude);
  world.starts = ChooseStarts(world, Modality::kUav, kAltitude, 5, rng);
}

}  // namespace

World RoadVehiclesScene(uint64_t seed) {
  Rng rng(seed);
  World world = Base("outdoor_road_vehicles", "seed 000 scene (a): vehicles by a road", 45, 48);
  const std::vector<std::array<double, 4>> roads = {{0, 20, 45, 27}, {30, 0, 36, 48}};
  for (const auto& r : roads)
    world.obstacles.push_back(parts::Surface("road", kRoad, r[0], r[1], r[2], r[3]));
  // Hedges block the view across the quarters.
  world.obstacles.push_back(Obstacle{"hedge", Rgb{40, 110, 40}, Box(14, 17, 12, 1.0, 2.5)});
  world.obstacles.push_back(Obstacle{"hedge", Rgb{40, 110, 40}, Box(27, 36, 1.0, 10, 2.5)});
  // Vehicles: one parked along the north-south road, one at the crossing's corner.
  AddObject(world, "car", kCar,
            Box(37.5, rng.Uniform(32, 44), 4.4, 1.8, 1.5, std::numbers::pi / 2));
  AddObject(world, "car", kCarBlue, Box(rng.Uniform(3, 12), 25.2, 4.4, 1.8, 1.5));
  ScatterTrees(world, rng, 24, 1, 1, 44, 47, roads);
  ScatterBoxes(world, rng, 6, {2, 2, 43, 46}, {0.6, 0.6, 1.1}, false, 0.5,
               AsObstacle(world, "trash bin", kBin));
  ScatterBoxes(world, rng, 3, {2, 2, 43, 46}, {3.0, 0.4, 0.5}, true, 0.5,
               AsObstacle(world, "fallen pole", kConcrete));
  ScatterBoxes(world, rng, 2, {2, 2, 43, 46}, {1.8, 0.6, 0.9}, true, 0.8,
               AsObject(world, "bench", kBench));
  Finish(world, rng);
  return world;
}

World BuildingVehiclesScene(uint64_t seed) {
  Rng rng(seed);
  World world =
      Base("outdoor_building_vehicles", "seed 000 scene (b): vehicles around a building", 40, 40);
  world.obstacles.push_back(parts::Surface("road", kRoad, 0, 4, 40, 10));
  world.obstacles.push_back(
      Obstacle{"building", Rgb{200, 180, 160},
               PrismShape{{{12, 14}, {28, 14}, {28, 22}, {20, 22}, {20, 30}, {12, 30}}, 0.0, 8.0}});
  // A carport in the building's inner corner hides one car from above.
  for (const auto& [x, y] :
       std::vector<std::pair<double, double>>{{21, 23}, {27, 23}, {21, 29}, {27, 29}}) {
    world.obstacles.push_back(Obstacle{"post", kConcrete, Box(x, y, 0.2, 0.2, 2.6)});
  }
  world.obstacles.push_back(Obstacle{"roof", kConcrete, Box(24, 26, 6.6, 6.6, 0.2, 0.0, 2.6)});
  AddObject(world, "car", kCar, Box(24, 26, 4.4, 1.8, 1.5, std::numbers::pi / 2));
  AddObject(world, "car", kCarBlue, Box(rng.Uniform(10, 22), 34.5, 4.4, 1.8, 1.5));
  world.obstacles.push_back(Obstacle{"fence", Rgb{150, 120, 90}, Box(34, 22, 0.2, 16, 1.2)});
  world.obstacles.push_back(Obstacle{"fence", Rgb{150, 120, 90}, Box(6, 26, 0.2, 12, 1.2)});
  ScatterTrees(world, rng, 12, 1, 11, 39, 39, {{12, 14, 28, 30}});
  ScatterBoxes(world, rng, 4, {2, 11, 38, 38}, {0.6, 0.6, 1.1}, false, 0.5,
               AsObstacle(world, "trash bin", kBin));
  Finish(world, rng);
  return world;
}

World RiverBridgeScene(uint64_t seed) {
  Rng rng(seed);
  World world = Base("outdoor_river_bridge", "seed 000 scene (c): a bridge across a river", 65, 47);
  world.obstacles.push_back(parts::Surface("river", kWater, 28, 0, 36, 47));
  const double y = rng.Uniform(10, 37);
  AddObject(world, "bridge", kConcrete, Box(32, y, 12, 4, 1.2));
  world.obstacles.push_back(parts::Surface("road", kRoad, 0, y - 2, 26, y + 2));
  world.obstacles.push_back(parts::Surface("road", kRoad, 38, y - 2, 65, y + 2));
  AddObject(world, "boat", Rgb{200, 200, 60},
            Box(32, y > 23 ? y - 12 : y + 12, 3.0, 1.2, 0.8, std::numbers::pi / 2));
  const std::vector<std::array<double, 4>> keep = {{26, 0, 38, 47}, {0, y - 2, 65, y + 2}};
  ScatterTrees(world, rng, 22, 1, 1, 27, 46, keep);
  ScatterTrees(world, rng, 22, 37, 1, 64, 46, keep);
  ScatterBoxes(world, rng, 3, {2, 2, 26, 45}, {1.8, 0.6, 0.9}, true, 0.8,
               AsObject(world, "bench", kBench));
  RemoveUnreachableObjects(world, Modality::kUav, kAltitude);
  // Starts on the west bank, away from the bridge.
  World west = world;
  west.bounds_max.x() = 24;
  world.starts = ChooseStarts(west, Modality::kUav, kAltitude, 5, rng);
  return world;
}

}  // namespace semnav::sim
