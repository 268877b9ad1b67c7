#include "services/relocalization/core/landmark_store.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/relocalization/core/landmark_map_file.h"

namespace semnav::relocalization {
namespace {

constexpr char kExtension[] = ".lmap";

absl::Status MapNotFound(absl::string_view map_id) {
  return FieldStatus(absl::StatusCode::kNotFound, "map_id",
                     absl::StrCat("no landmark map \"", map_id, "\""), "MAP_NOT_FOUND");
}

}  // namespace

absl::Status ValidateMapId(absl::string_view map_id) {
  const bool chars_ok = std::all_of(map_id.begin(), map_id.end(), [](char c) {
    return absl::ascii_isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (map_id.empty() || map_id.size() > 128 || map_id.front() == '.' || !chars_ok) {
    // Preview: a 1 MB id is never echoed back.
    return InvalidField("map_id", absl::StrCat("must be 1-128 characters of [A-Za-z0-9_.-] not "
                                               "starting with '.', got \"",
                                               Preview(map_id), "\""));
  }
  return absl::OkStatus();
}

absl::StatusOr<std::unique_ptr<LandmarkStore>> LandmarkStore::Open(const std::string& folder,
                                                                   const MergeParams& merge) {
  std::unique_ptr<LandmarkStore> store(new LandmarkStore(folder, merge));
  if (folder.empty()) return store;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec)
    return absl::FailedPreconditionError(
        absl::StrCat("storage folder ", folder, ": ", ec.message()));
  absl::MutexLock lock(&store->mu_);
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::filesystem::path& path = entry.path();
    if (path.extension() != kExtension) continue;
    const std::string map_id = path.stem().string();
    absl::StatusOr<LandmarkMap> map = ReadLandmarkMapFile(path.string());
    if (map.ok()) {
      store->maps_[map_id] = std::make_shared<const LandmarkMap>(*std::move(map));
    } else {
      store->corrupt_[map_id] = map.status();
    }
  }
  return store;
}

std::string LandmarkStore::PathOf(absl::string_view map_id) const {
  return (std::filesystem::path(folder_) / absl::StrCat(map_id, kExtension)).string();
}

absl::Status LandmarkStore::CheckNotCorrupt(absl::string_view map_id) const {
  const auto it = corrupt_.find(map_id);
  return it == corrupt_.end() ? absl::OkStatus() : it->second;
}

absl::StatusOr<std::shared_ptr<const LandmarkMap>> LandmarkStore::Get(
    absl::string_view map_id) const {
  if (auto s = ValidateMapId(map_id); !s.ok()) return s;
  absl::ReaderMutexLock lock(&mu_);
  if (auto s = CheckNotCorrupt(map_id); !s.ok()) return s;
  const auto it = maps_.find(map_id);
  if (it == maps_.end()) {
    return MapNotFound(map_id);
  }
  return it->second;
}

absl::StatusOr<UpsertSummary> LandmarkStore::Upsert(absl::string_view map_id,
                                                    std::vector<Landmark> landmarks) {
  if (auto s = ValidateMapId(map_id); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  if (auto s = CheckNotCorrupt(map_id); !s.ok()) return s;
  const auto it = maps_.find(map_id);
  LandmarkMap next = it == maps_.end() ? LandmarkMap() : *it->second;
  absl::StatusOr<UpsertSummary> summary = next.Upsert(std::move(landmarks), merge_);
  if (!summary.ok()) return summary;
  if (!folder_.empty()) {
    if (auto s = WriteLandmarkMapFile(PathOf(map_id), next); !s.ok()) return s;
  }
  maps_[std::string(map_id)] = std::make_shared<const LandmarkMap>(std::move(next));
  return summary;
}

absl::Status LandmarkStore::Delete(absl::string_view map_id) {
  if (auto s = ValidateMapId(map_id); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  const auto it = maps_.find(map_id);
  const auto bad = corrupt_.find(map_id);
  if (it == maps_.end() && bad == corrupt_.end()) {
    return MapNotFound(map_id);
  }
  if (!folder_.empty()) {
    std::error_code ec;
    std::filesystem::remove(PathOf(map_id), ec);
    if (ec) return absl::InternalError(absl::StrCat("delete ", PathOf(map_id), ": ", ec.message()));
  }
  if (it != maps_.end()) maps_.erase(it);
  if (bad != corrupt_.end()) corrupt_.erase(bad);
  return absl::OkStatus();
}

}  // namespace semnav::relocalization
