// semnav-sim-worlds --out DIR [--seed N] [--data DIR]: writes the benchmark suite folders
// (indoor, outdoor, flyroll, houseexpo, fr079) of world YAML files.
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>

#include "clients/sim/worlds/benchmark_suite.h"

namespace {

constexpr char kUsage[] =
    "usage: semnav-sim-worlds --out DIR [--seed N] [--data DIR]\n"
    "  --out DIR   folder to write <suite>/<world>.yaml into (created)\n"
    "  --seed N    world generation seed (default 1)\n"
    "  --data DIR  shared data folder with floorplans/ and pointclouds-octomaps/\n"
    "              (default " SEMNAV_SHARED_DATA_DIR ")\n";

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> flags = {{"--seed", "1"}, {"--data", SEMNAV_SHARED_DATA_DIR}};
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << kUsage;
      return 0;
    }
    if ((arg == "--out" || arg == "--seed" || arg == "--data") && i + 1 < argc) {
      flags[arg] = argv[++i];
    } else {
      std::cerr << "semnav-sim-worlds: unknown or incomplete argument " << arg << "\n" << kUsage;
      return 2;
    }
  }
  if (!flags.contains("--out")) {
    std::cerr << "semnav-sim-worlds: --out is required\n" << kUsage;
    return 2;
  }
  char* end = nullptr;
  const unsigned long long seed = std::strtoull(flags["--seed"].c_str(), &end, 10);
  if (end == nullptr || *end != '\0' || flags["--seed"].empty()) {
    std::cerr << "semnav-sim-worlds: --seed must be a non-negative integer\n";
    return 2;
  }
  const auto worlds = semnav::sim::BuildBenchmarkSuite(seed, flags["--data"]);
  if (!worlds.ok()) {
    std::cerr << "semnav-sim-worlds: " << worlds.status() << "\n";
    return 1;
  }
  const absl::Status written = semnav::sim::WriteBenchmarkSuite(*worlds, flags["--out"]);
  if (!written.ok()) {
    std::cerr << "semnav-sim-worlds: " << written << "\n";
    return 1;
  }
  for (const auto& w : *worlds) {
    std::cout << w.suite << "/" << w.world.name << ".yaml: " << w.world.objects.size()
              << " objects, " << w.world.obstacles.size() << " obstacles, " << w.world.rooms.size()
              << " rooms, " << w.world.starts.size() << " starts\n";
  }
  std::cout << "wrote " << worlds->size() << " worlds under " << flags["--out"] << "\n";
  return 0;
}
