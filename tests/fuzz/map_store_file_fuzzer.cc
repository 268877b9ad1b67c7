// Mapping's map files (services/mapping/core/map_store): "SNMAP1\n", payload size, CRC-32,
// payload. Inputs with an odd first byte are wrapped in a valid header and checksum, so the
// payload decoder behind the file checks is reached too; even ones are stored as they are.
#include <cstdint>
#include <cstdlib>

#include "services/mapping/core/map_serialization.h"
#include "services/mapping/core/map_store.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

void PutLittleEndian(std::string& out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  static const semnav::mapping::MapStore* store = [] {
    absl::StatusOr<semnav::mapping::MapStore> opened =
        semnav::mapping::MapStore::Open(semnav::fuzz::ScratchDir() + "/maps");
    if (!opened.ok()) std::abort();
    return new semnav::mapping::MapStore(*std::move(opened));
  }();
  std::string file = semnav::fuzz::AsString(data + 1, size - 1);
  if (data[0] & 1) {
    std::string payload = std::move(file);
    file = "SNMAP1\n";
    PutLittleEndian(file, payload.size(), 8);
    PutLittleEndian(file, semnav::mapping::Crc32(payload), 4);
    file += payload;
  }
  semnav::fuzz::WriteScratchFile("maps/fuzz.snmap", file);
  absl::StatusOr<std::string> payload = store->Load("fuzz");
  if (!payload.ok()) return 0;
  (void)semnav::mapping::ParseMap(*payload);
  return 0;
}
