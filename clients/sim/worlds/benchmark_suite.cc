#include "clients/sim/worlds/benchmark_suite.h"

#include <filesystem>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/world_yaml.h"
#include "clients/sim/worlds/flyroll_scenes.h"
#include "clients/sim/worlds/houseexpo_world.h"
#include "clients/sim/worlds/indoor_generator.h"
#include "clients/sim/worlds/octomap_world.h"
#include "clients/sim/worlds/outdoor_scenes.h"

namespace semnav::sim {
namespace {

uint64_t WorldSeed(uint64_t seed, const std::string& name) {
  return MixSeed(seed, HashString(name));
}

}  // namespace

absl::StatusOr<std::vector<SuiteWorld>> BuildBenchmarkSuite(uint64_t seed,
                                                            const std::string& shared_data_dir) {
  std::vector<SuiteWorld> worlds;
  for (Building building : {Building::kHome, Building::kOffice}) {
    for (int i = 1; i <= 4; ++i) {
      const std::string name =
          absl::StrFormat("%s_%02d", building == Building::kHome ? "home" : "office", i);
      IndoorOptions options;
      options.building = building;
      worlds.push_back({"indoor", GenerateIndoor(name, options, WorldSeed(seed, name))});
    }
  }
  worlds.push_back({"outdoor", RoadVehiclesScene(WorldSeed(seed, "road"))});
  worlds.push_back({"outdoor", BuildingVehiclesScene(WorldSeed(seed, "building"))});
  worlds.push_back({"outdoor", RiverBridgeScene(WorldSeed(seed, "river"))});
  for (int i = 1; i <= 2; ++i) {
    const std::string name = absl::StrFormat("flyroll_%02d", i);
    worlds.push_back({"flyroll", FlyRollScene(name, WorldSeed(seed, name))});
  }
  for (const char* plan : {"house_expo_room_0000", "house_expo_room_1451"}) {
    const std::string path =
        absl::StrCat(shared_data_dir, "/floorplans/houseexpo_samples/", plan, ".json");
    absl::StatusOr<World> world = HouseExpoWorld(path, plan, WorldSeed(seed, plan));
    if (!world.ok()) return world.status();
    worlds.push_back({"houseexpo", *std::move(world)});
  }
  const std::string bt = shared_data_dir + "/pointclouds-octomaps/octomap_share/geb079.bt";
  absl::StatusOr<World> fr079 = OctomapWorld(bt, "fr079_corridor", WorldSeed(seed, "fr079"));
  if (!fr079.ok()) return fr079.status();
  worlds.push_back({"fr079", *std::move(fr079)});
  return worlds;
}

absl::Status WriteBenchmarkSuite(const std::vector<SuiteWorld>& worlds,
                                 const std::string& out_dir) {
  for (const SuiteWorld& w : worlds) {
    const std::filesystem::path folder = std::filesystem::path(out_dir) / w.suite;
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    if (error) return absl::InternalError(absl::StrCat("cannot create ", folder.string()));
    const absl::Status status =
        SaveWorldFile(w.world, (folder / (w.world.name + ".yaml")).string());
    if (!status.ok()) return status;
  }
  return absl::OkStatus();
}

}  // namespace semnav::sim
