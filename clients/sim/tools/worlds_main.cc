// semnav-sim-worlds --out DIR [--seed N] [--data DIR]: writes the benchmark suite folders
// (indoor, outdoor, flyroll, houseexpo, fr079) of world YAML files.
#include <cstdlib>
#include <iostream>
#include <string>

#include "clients/sim/worlds/benchmark_suite.h"
#include "services/common/cli/flags.h"

namespace {

constexpr char kUsage[] =
    "usage: semnav-sim-worlds --out DIR [--seed N] [--data DIR]\n"
    "  --out DIR   folder to write <suite>/<world>.yaml into (created)\n"
    "  --seed N    world generation seed (default 1)\n"
    "  --data DIR  shared data folder with floorplans/ and pointclouds-octomaps/\n"
    "              (default " SEMNAV_SHARED_DATA_DIR ")\n";

}  // namespace

int main(int argc, char** argv) {
  const semnav::ParsedFlags flags = semnav::ParseFlagsOrExit(
      argc, argv, {{"out", "DIR", ""}, {"seed", "N", ""}, {"data", "DIR", ""}}, "semnav-sim-worlds",
      kUsage);
  const std::string seed_text = flags.Get("seed").value_or("1");
  const std::string data_dir = flags.Get("data").value_or(SEMNAV_SHARED_DATA_DIR);
  const std::string out_dir = flags.Get("out").value_or("");
  if (!flags.Has("out")) {
    std::cerr << "semnav-sim-worlds: --out is required\n" << kUsage;
    return 2;
  }
  char* end = nullptr;
  const unsigned long long seed = std::strtoull(seed_text.c_str(), &end, 10);
  if (end == nullptr || *end != '\0' || seed_text.empty()) {
    std::cerr << "semnav-sim-worlds: --seed must be a non-negative integer\n";
    return 2;
  }
  const auto worlds = semnav::sim::BuildBenchmarkSuite(seed, data_dir);
  if (!worlds.ok()) {
    std::cerr << "semnav-sim-worlds: " << worlds.status() << "\n";
    return 1;
  }
  const absl::Status written = semnav::sim::WriteBenchmarkSuite(*worlds, out_dir);
  if (!written.ok()) {
    std::cerr << "semnav-sim-worlds: " << written << "\n";
    return 1;
  }
  for (const auto& w : *worlds) {
    std::cout << w.suite << "/" << w.world.name << ".yaml: " << w.world.objects.size()
              << " objects, " << w.world.obstacles.size() << " obstacles, " << w.world.rooms.size()
              << " rooms, " << w.world.starts.size() << " starts\n";
  }
  std::cout << "wrote " << worlds->size() << " worlds under " << out_dir << "\n";
  return 0;
}
