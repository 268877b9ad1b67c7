// Mapping's saved-map payload (services/mapping/core/map_serialization): the OcTree section,
// the scene graph as JSON, the labelled points as JSON and the saved grid.
#include <cstdint>

#include "services/mapping/core/map_serialization.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  (void)semnav::mapping::ParseMap(semnav::fuzz::AsString(data, size));
  return 0;
}
