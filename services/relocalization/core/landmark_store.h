#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "absl/synchronization/mutex.h"
#include "services/relocalization/core/landmark_map.h"

namespace semnav::relocalization {

// INVALID_ARGUMENT naming "map_id" unless it is 1-128 of [A-Za-z0-9_.-], not starting with '.'.
absl::Status ValidateMapId(absl::string_view map_id);

// Landmark maps by map id, thread-safe. With a folder, every change is persisted
// (`<folder>/<map_id>.lmap`, crash-safe) before it becomes visible; a map whose file is
// corrupt answers DATA_LOSS to reads and upserts and its file is never overwritten
// (only Delete removes it).
class LandmarkStore {
 public:
  // folder empty = memory only. Loads every .lmap file of an existing folder.
  static absl::StatusOr<std::unique_ptr<LandmarkStore>> Open(const std::string& folder,
                                                             const MergeParams& merge);

  // Immutable snapshot; NOT_FOUND naming map_id when unknown.
  absl::StatusOr<std::shared_ptr<const LandmarkMap>> Get(absl::string_view map_id) const;
  // Creates the map on first use. Nothing changes on error.
  absl::StatusOr<UpsertSummary> Upsert(absl::string_view map_id, std::vector<Landmark> landmarks);
  absl::Status Delete(absl::string_view map_id);

 private:
  LandmarkStore(std::string folder, const MergeParams& merge)
      : folder_(std::move(folder)), merge_(merge) {}
  std::string PathOf(absl::string_view map_id) const;
  absl::Status CheckNotCorrupt(absl::string_view map_id) const ABSL_SHARED_LOCKS_REQUIRED(mu_);

  const std::string folder_;
  const MergeParams merge_;
  mutable absl::Mutex mu_;
  std::map<std::string, std::shared_ptr<const LandmarkMap>, std::less<>> maps_ ABSL_GUARDED_BY(mu_);
  std::map<std::string, absl::Status, std::less<>> corrupt_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::relocalization
