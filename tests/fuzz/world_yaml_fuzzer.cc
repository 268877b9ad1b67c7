// World files of the simulator (clients/sim/core/world_yaml, through ConfigReader): any text either
// parses into a world or is an error, and a parsed world writes back to YAML that parses again.
#include <cstdint>
#include <cstdlib>

#include "clients/sim/core/world_yaml.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  absl::StatusOr<semnav::sim::World> world =
      semnav::sim::ParseWorldYaml(semnav::fuzz::AsString(data, size));
  if (!world.ok()) return 0;
  // What was accepted must survive its own round trip.
  if (!semnav::sim::ParseWorldYaml(semnav::sim::WorldToYaml(*world)).ok()) std::abort();
  return 0;
}
