#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"

namespace semnav::mapping {

struct StoredMap {
  std::string map_id;
  uint64_t size_bytes = 0;
  int64_t saved_ns = 0;
};

// Named map files in one directory, crash-safe (storage::WriteFileAtomically): a crash leaves
// either the old or the new <id>.snmap. Files are the checksummed frame of
// storage::FrameWithChecksum with magic "SNMAP1\n"; a file whose header, size or checksum does not
// match loads as DATA_LOSS.
class MapStore {
 public:
  // Creates the directory if needed.
  static absl::StatusOr<MapStore> Open(const std::string& directory);

  absl::StatusOr<StoredMap> Save(const std::string& map_id, const std::string& payload) const;
  // NOT_FOUND when absent, DATA_LOSS when corrupt.
  absl::StatusOr<std::string> Load(const std::string& map_id) const;
  absl::StatusOr<std::vector<StoredMap>> List() const;
  absl::Status Delete(const std::string& map_id) const;
  absl::StatusOr<StoredMap> Stat(const std::string& map_id) const;

  // INVALID_ARGUMENT naming "map_id" unless 1-64 characters of [A-Za-z0-9_-].
  static absl::Status ValidateMapId(const std::string& map_id);

 private:
  explicit MapStore(std::string directory) : directory_(std::move(directory)) {}
  std::string PathOf(const std::string& map_id) const;

  std::string directory_;
};

}  // namespace semnav::mapping
