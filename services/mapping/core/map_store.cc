#include "services/mapping/core/map_store.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/storage/durable_file.h"

namespace semnav::mapping {
namespace {

constexpr char kMagic[] = "SNMAP1\n";
constexpr char kSuffix[] = ".snmap";

absl::Status NoStoredMap(absl::string_view map_id) {
  return FieldStatus(absl::StatusCode::kNotFound, "map_id",
                     absl::StrCat("no stored map '", map_id, "'"), "NOT_FOUND");
}

}  // namespace

absl::Status MapStore::ValidateMapId(const std::string& map_id) {
  const bool ok = !map_id.empty() && map_id.size() <= 64 &&
                  std::all_of(map_id.begin(), map_id.end(), [](char c) {
                    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
                  });
  if (ok) return absl::OkStatus();
  return InvalidField(
      "map_id", absl::StrCat("'", Preview(map_id), "' must be 1-64 characters of [A-Za-z0-9_-]"));
}

absl::StatusOr<MapStore> MapStore::Open(const std::string& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    return absl::InternalError(
        absl::StrCat("cannot create map directory ", directory, ": ", error.message()));
  return MapStore(directory);
}

std::string MapStore::PathOf(const std::string& map_id) const {
  return absl::StrCat(directory_, "/", map_id, kSuffix);
}

absl::StatusOr<StoredMap> MapStore::Save(const std::string& map_id,
                                         const std::string& payload) const {
  if (absl::Status s = ValidateMapId(map_id); !s.ok()) return s;
  if (absl::Status s = storage::WriteFramedFileAtomically(PathOf(map_id), kMagic, payload);
      !s.ok()) {
    return s;
  }
  return Stat(map_id);
}

absl::StatusOr<std::string> MapStore::Load(const std::string& map_id) const {
  if (absl::Status s = ValidateMapId(map_id); !s.ok()) return s;
  absl::StatusOr<std::string> file = storage::ReadWholeFile(PathOf(map_id));
  if (absl::IsNotFound(file.status())) return NoStoredMap(map_id);
  if (!file.ok()) return file.status();
  absl::StatusOr<std::string> payload =
      storage::PayloadOfFrame(kMagic, *file, absl::StrCat("stored map '", map_id, "'"));
  if (!payload.ok()) return WithField(payload.status(), "map_id");
  return payload;
}

absl::StatusOr<StoredMap> MapStore::Stat(const std::string& map_id) const {
  std::error_code error;
  const std::string path = PathOf(map_id);
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (error) return NoStoredMap(map_id);
  const auto written = std::filesystem::last_write_time(path, error);
  const auto system_time = std::chrono::file_clock::to_sys(written);
  return StoredMap{
      map_id, size,
      std::chrono::duration_cast<std::chrono::nanoseconds>(system_time.time_since_epoch()).count()};
}

absl::StatusOr<std::vector<StoredMap>> MapStore::List() const {
  std::vector<StoredMap> maps;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(directory_, error)) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != kSuffix) continue;
    const std::string id = name.substr(0, name.size() - std::strlen(kSuffix));
    absl::StatusOr<StoredMap> info = Stat(id);
    if (info.ok()) maps.push_back(*info);
  }
  if (error)
    return absl::InternalError(absl::StrCat("cannot list ", directory_, ": ", error.message()));
  std::sort(maps.begin(), maps.end(),
            [](const StoredMap& a, const StoredMap& b) { return a.map_id < b.map_id; });
  return maps;
}

absl::Status MapStore::Delete(const std::string& map_id) const {
  if (absl::Status s = ValidateMapId(map_id); !s.ok()) return s;
  const absl::Status removed = storage::RemoveFileDurably(PathOf(map_id));
  if (absl::IsNotFound(removed)) return NoStoredMap(map_id);
  return removed;
}

}  // namespace semnav::mapping
