#include "services/relocalization/core/landmark_map.h"

#include <unordered_map>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::relocalization {
namespace {

// Observation-weighted mean of two estimates of the same object.
void Fuse(Landmark& into, const Landmark& from) {
  const double wa = into.observations, wb = from.observations, w = wa + wb;
  into.position = (wa * into.position + wb * from.position) / w;
  into.scale = (wa * into.scale + wb * from.scale) / w;
  for (size_t d = 0; d < into.descriptor.size(); ++d) {
    into.descriptor[d] =
        static_cast<float>((wa * into.descriptor[d] + wb * from.descriptor[d]) / w);
  }
  into.observations += from.observations;
}

bool SameObject(const Landmark& a, const Landmark& b, const MergeParams& params) {
  return (a.position - b.position).norm() < params.radius_m &&
         DescriptorLabel(a.descriptor) == DescriptorLabel(b.descriptor) &&
         CosineSimilarity(a.descriptor, b.descriptor) >= params.min_descriptor_similarity;
}

}  // namespace

LandmarkMap::LandmarkMap(std::vector<Landmark> landmarks, uint64_t next_id, uint64_t revision)
    : index_(std::make_shared<IndexedLandmarks>(std::move(landmarks))),
      next_id_(next_id),
      revision_(revision) {}

size_t LandmarkMap::descriptor_dim() const {
  return landmarks().empty() ? 0 : landmarks().front().descriptor.size();
}

absl::StatusOr<UpsertSummary> LandmarkMap::Upsert(std::vector<Landmark> incoming,
                                                  const MergeParams& params) {
  if (incoming.empty()) return InvalidField("landmarks", "must contain at least one landmark");
  if (auto s = CheckCount(incoming.size(), "landmarks", kMaxLandmarksPerRequest); !s.ok()) return s;
  const size_t dim = descriptor_dim() != 0 ? descriptor_dim() : incoming.front().descriptor.size();
  std::unordered_map<uint64_t, size_t> slot_of_id;
  for (size_t i = 0; i < landmarks().size(); ++i) slot_of_id[landmarks()[i].id] = i;
  for (size_t i = 0; i < incoming.size(); ++i) {
    const std::string field = absl::StrCat("landmarks[", i, "]");
    if (auto s = ValidateLandmark(incoming[i], dim, field); !s.ok()) return s;
    if (incoming[i].observations == 0) {
      return InvalidField(absl::StrCat(field, ".observations"), "must be >= 1");
    }
    if (incoming[i].id != 0 && !slot_of_id.contains(incoming[i].id)) {
      return FieldStatus(absl::StatusCode::kNotFound, absl::StrCat(field, ".id"),
                         absl::StrCat("no landmark ", incoming[i].id, " in this map"),
                         "LANDMARK_NOT_FOUND");
    }
  }

  std::vector<Landmark> next = landmarks();
  const size_t stored = next.size();
  UpsertSummary summary;
  for (Landmark& l : incoming) {
    if (l.id != 0) {
      summary.ids.push_back(l.id);
      next[slot_of_id[l.id]] = std::move(l);
      ++summary.replaced;
      continue;
    }
    // Same object among the stored landmarks (KD-tree) or those added by this call.
    Landmark* same = nullptr;
    for (size_t m : index_->tree().WithinRadius(l.position, params.radius_m)) {
      if (SameObject(next[m], l, params)) {
        same = &next[m];
        break;
      }
    }
    for (size_t m = stored; same == nullptr && m < next.size(); ++m) {
      if (SameObject(next[m], l, params)) same = &next[m];
    }
    if (same != nullptr) {
      Fuse(*same, l);
      summary.ids.push_back(same->id);
      ++summary.merged;
    } else {
      l.id = next_id_++;
      summary.ids.push_back(l.id);
      next.push_back(std::move(l));
      ++summary.inserted;
    }
  }
  index_ = std::make_shared<IndexedLandmarks>(std::move(next));
  summary.revision = ++revision_;
  return summary;
}

}  // namespace semnav::relocalization
