#include "services/mapping/landmarks/saved_landmarks.h"

#include "absl/strings/str_cat.h"
#include "services/common/storage/durable_file.h"
#include "services/relocalization/core/landmark_map_file.h"

namespace semnav::mapping {

std::string SavedLandmarksPath(const std::string& directory, const std::string& map_id) {
  return absl::StrCat(directory, "/", map_id, ".lmap");
}

absl::Status SaveLandmarks(const std::string& directory, const std::string& map_id,
                           const std::vector<SceneLandmark>& landmarks) {
  std::vector<relocalization::Landmark> stored;
  stored.reserve(landmarks.size());
  for (const SceneLandmark& item : landmarks) {
    stored.push_back(item.landmark);
    stored.back().id = stored.size();
  }
  const uint64_t next_id = stored.size() + 1;
  const relocalization::LandmarkMap map(std::move(stored), next_id, /*revision=*/1);
  return relocalization::WriteLandmarkMapFile(SavedLandmarksPath(directory, map_id), map);
}

absl::StatusOr<relocalization::LandmarkMap> LoadLandmarks(const std::string& directory,
                                                          const std::string& map_id) {
  absl::StatusOr<relocalization::LandmarkMap> map =
      relocalization::ReadLandmarkMapFile(SavedLandmarksPath(directory, map_id));
  if (absl::IsNotFound(map.status())) {
    return absl::NotFoundError(
        absl::StrCat("map_id: stored map '", map_id, "' has no landmark map"));
  }
  if (!map.ok()) {
    return absl::Status(map.status().code(), absl::StrCat("map_id: landmark map of '", map_id,
                                                          "': ", map.status().message()));
  }
  return map;
}

absl::Status DeleteLandmarks(const std::string& directory, const std::string& map_id) {
  const absl::Status removed = storage::RemoveFileDurably(SavedLandmarksPath(directory, map_id));
  return absl::IsNotFound(removed) ? absl::OkStatus() : removed;
}

}  // namespace semnav::mapping
