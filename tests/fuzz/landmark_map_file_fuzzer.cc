// Relocalization's landmark map files (services/relocalization/core/landmark_map_file): a header,
// landmarks and an FNV-1a 64 checksum. Inputs with an odd first byte get the right checksum
// appended, so the landmark decoder behind the check is reached; even ones are read as they are.
#include <cstdint>

#include "services/relocalization/core/landmark_map_file.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

uint64_t Fnv1a64(const std::string& bytes) {  // the file's checksum, as the format documents it
  uint64_t h = 14695981039346656037ull;
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  std::string file = semnav::fuzz::AsString(data + 1, size - 1);
  if (data[0] & 1) {
    const uint64_t sum = Fnv1a64(file);
    file.append(reinterpret_cast<const char*>(&sum), sizeof(sum));
  }
  (void)semnav::relocalization::ReadLandmarkMapFile(
      semnav::fuzz::WriteScratchFile("landmarks.snlm", file));
  return 0;
}
