// Small helpers shared by the harnesses: the fuzz input as a string, and a private scratch folder
// for decoders that read files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace semnav::fuzz {

inline std::string AsString(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A folder of this process, created on first use (under TMPDIR) and reused.
const std::string& ScratchDir();

// Writes `bytes` to ScratchDir()/name and returns the path; aborts if it cannot.
std::string WriteScratchFile(const std::string& name, const std::string& bytes);

}  // namespace semnav::fuzz
