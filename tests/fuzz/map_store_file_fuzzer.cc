// Mapping's map files (services/mapping/core/map_store): storage::FrameWithChecksum with magic
// "SNMAP1\n". Inputs with an odd first byte are wrapped in a valid frame, so the payload decoder
// behind the file checks is reached too; even ones are stored as they are.
#include <cstdint>
#include <cstdlib>

#include "services/common/storage/durable_file.h"
#include "services/mapping/core/map_serialization.h"
#include "services/mapping/core/map_store.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const semnav::mapping::MapStore* store = [] {
    absl::StatusOr<semnav::mapping::MapStore> opened =
        semnav::mapping::MapStore::Open(semnav::fuzz::ScratchDir() + "/maps");
    if (!opened.ok()) std::abort();
    return new semnav::mapping::MapStore(*std::move(opened));
  }();
  std::string file = semnav::fuzz::AsString(data + 1, size - 1);
  if (data[0] & 1) file = semnav::storage::FrameWithChecksum("SNMAP1\n", file);
  semnav::fuzz::WriteScratchFile("maps/fuzz.snmap", file);
  absl::StatusOr<std::string> payload = store->Load("fuzz");
  if (!payload.ok()) return 0;
  (void)semnav::mapping::ParseMap(*payload);
  return 0;
}
