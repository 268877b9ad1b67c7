// The landmark map saved beside a mapping store's occupancy map: `<directory>/<map_id>.lmap`,
// in the relocalization service's own landmark map file format (one format, crash-safe writes),
// so a saved map id names both the occupancy map and its landmarks.
#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/mapping/landmarks/scene_landmarks.h"
#include "services/relocalization/core/landmark_map.h"

namespace semnav::mapping {

std::string SavedLandmarksPath(const std::string& directory, const std::string& map_id);

// Writes `landmarks` (ids assigned 1..n in order) as map `map_id`'s landmark map, atomically.
// `map_id` must already be valid (MapStore::ValidateMapId).
absl::Status SaveLandmarks(const std::string& directory, const std::string& map_id,
                           const std::vector<SceneLandmark>& landmarks);

// NOT_FOUND when the map was saved without landmarks; DATA_LOSS when the file is corrupt.
absl::StatusOr<relocalization::LandmarkMap> LoadLandmarks(const std::string& directory,
                                                          const std::string& map_id);

// Removes the file; OK when there was none.
absl::Status DeleteLandmarks(const std::string& directory, const std::string& map_id);

}  // namespace semnav::mapping
