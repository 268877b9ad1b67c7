#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "services/relocalization/core/indexed_landmarks.h"

namespace semnav::relocalization {

// When an incoming landmark is the same object as a stored one (landmark merge).
struct MergeParams {
  double radius_m = 0.3;                   // centres closer than this ...
  double min_descriptor_similarity = 0.9;  // ... with the same label and cosine >= this
};

// What an upsert did.
struct UpsertSummary {
  size_t inserted = 0;
  size_t merged = 0;          // fused into an existing landmark of the same object
  size_t replaced = 0;        // given with an existing id and overwritten
  std::vector<uint64_t> ids;  // resulting id of each incoming landmark, in order
  uint64_t revision = 0;
};

// One robot's landmark map: landmarks with stable ids, a descriptor length fixed by the
// first upsert, a revision bumped by every change, and the retrieval indexes.
class LandmarkMap {
 public:
  LandmarkMap() : index_(std::make_shared<IndexedLandmarks>()) {}
  // Restores a persisted map as is (no merging).
  LandmarkMap(std::vector<Landmark> landmarks, uint64_t next_id, uint64_t revision);

  // Validates every landmark first (errors name "landmarks[i]..."; nothing changes on
  // error). Landmarks with id 0 are merged into a stored landmark of the same object or
  // inserted with a fresh id; a non-zero id must exist (NOT_FOUND) and is replaced.
  absl::StatusOr<UpsertSummary> Upsert(std::vector<Landmark> landmarks, const MergeParams& params);

  const std::vector<Landmark>& landmarks() const { return index_->landmarks(); }
  // Immutable snapshot with the hash and KD-tree indexes; safe to use while the map changes.
  std::shared_ptr<const IndexedLandmarks> index() const { return index_; }
  size_t descriptor_dim() const;
  uint64_t next_id() const { return next_id_; }
  uint64_t revision() const { return revision_; }

 private:
  std::shared_ptr<const IndexedLandmarks> index_;
  uint64_t next_id_ = 1;
  uint64_t revision_ = 0;
};

}  // namespace semnav::relocalization
