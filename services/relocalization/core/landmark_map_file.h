#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "services/relocalization/core/landmark_map.h"

namespace semnav::relocalization {

// Crash-safe persistence of one landmark map: the bytes go to "<path>.tmp", are
// fsync'ed, renamed over `path`, and the folder is fsync'ed, so a crash leaves either
// the old or the new file. The file ends with an FNV-1a 64 checksum of its contents.
absl::Status WriteLandmarkMapFile(const std::string& path, const LandmarkMap& map);

// NOT_FOUND when the file is missing; DATA_LOSS when it is truncated, has a bad
// header or its checksum does not match.
absl::StatusOr<LandmarkMap> ReadLandmarkMapFile(const std::string& path);

}  // namespace semnav::relocalization
