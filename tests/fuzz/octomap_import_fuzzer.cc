// The simulator's OctoMap import (clients/sim/worlds/octomap_world): a .bt file becomes a world.
#include <cstdint>

#include "clients/sim/worlds/octomap_world.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      semnav::fuzz::WriteScratchFile("world.bt", semnav::fuzz::AsString(data, size));
  (void)semnav::sim::OctomapWorld(path, "fuzz", /*seed=*/1);
  return 0;
}
