#include "services/mapping/landmarks/scene_landmarks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::mapping {
namespace {

// Labels are names; a vocabulary longer than the descriptor budget is a mistake anyway.
constexpr size_t kMaxLabelBytes = kMaxIdBytes;

// Label shares over `labels` (score of each / all scores, also those outside the list).
void FillLabelBlock(const SceneObject& object, const std::vector<std::string>& labels, float* out) {
  double total = 0.0;
  for (const auto& [label, score] : object.label_scores) {
    if (std::isfinite(score) && score > 0.0) total += score;
  }
  if (total <=
      0.0) {  // no score history (a restored or hand-made instance): its label counts whole
    for (size_t i = 0; i < labels.size(); ++i) out[i] = labels[i] == object.label ? 1.0f : 0.0f;
    return;
  }
  for (size_t i = 0; i < labels.size(); ++i) {
    const auto it = object.label_scores.find(labels[i]);
    const double score = it == object.label_scores.end() ? 0.0 : it->second;
    out[i] = std::isfinite(score) && score > 0.0 ? static_cast<float>(score / total) : 0.0f;
  }
}

void FillEmbeddingBlock(const std::vector<float>& embedding, size_t dim, double weight,
                        float* out) {
  std::fill(out, out + dim, 0.0f);
  if (embedding.size() != dim) return;
  double norm2 = 0.0;
  for (float v : embedding) {
    if (!std::isfinite(v)) return;
    norm2 += static_cast<double>(v) * v;
  }
  if (!(norm2 > 0.0)) return;
  const double scale = weight / std::sqrt(norm2);
  for (size_t i = 0; i < dim; ++i) out[i] = static_cast<float>(embedding[i] * scale);
}

}  // namespace

absl::Status ValidateSceneLandmarkConfig(const SceneLandmarkConfig& config) {
  if (config.min_detections < 1 ||
      config.min_detections > static_cast<int>(relocalization::kMaxObservations)) {
    return InvalidField("min_detections",
                        absl::StrCat("must be in [1, ", relocalization::kMaxObservations, "]"));
  }
  std::set<std::string, std::less<>> seen;
  for (size_t i = 0; i < config.labels.size(); ++i) {
    const std::string field = absl::StrCat("labels[", i, "]");
    if (config.labels[i].empty()) return InvalidField(field, "must not be empty");
    if (absl::Status s = CheckLength(config.labels[i], field, kMaxLabelBytes); !s.ok()) return s;
    if (!seen.insert(config.labels[i]).second) {
      return InvalidField(field, absl::StrCat("'", Preview(config.labels[i]), "' is listed twice"));
    }
  }
  if (config.embedding_dim < 0)
    return InvalidField("embedding_dim", "must be >= 0 (0 = no embedding block)");
  const size_t dim = config.labels.size() + static_cast<size_t>(config.embedding_dim);
  if (dim == 0)
    return InvalidField("embedding_dim", "labels and embedding_dim are both empty: no descriptor");
  if (dim > relocalization::kMaxDescriptorDim) {
    return InvalidField("embedding_dim", absl::StrCat("labels + embedding_dim = ", dim,
                                                      " exceeds the descriptor limit ",
                                                      relocalization::kMaxDescriptorDim));
  }
  if (!std::isfinite(config.embedding_weight) || config.embedding_weight <= 0.0 ||
      config.embedding_weight > 10.0) {
    return InvalidField("embedding_weight", "must be in (0, 10]");
  }
  return absl::OkStatus();
}

size_t SceneLandmarkDescriptorDim(const SceneLandmarkConfig& config) {
  return config.labels.size() + static_cast<size_t>(std::max(config.embedding_dim, 0));
}

std::vector<SceneLandmark> LandmarksFromScene(const std::vector<SceneObject>& objects,
                                              const SceneLandmarkConfig& config) {
  const size_t labels = config.labels.size();
  const size_t dim = SceneLandmarkDescriptorDim(config);
  std::vector<SceneLandmark> out;
  for (const SceneObject& object : objects) {
    if (object.detection_count < config.min_detections) continue;
    if (object.pose_untrusted) continue;  // possibly in the wrong frame: never a landmark
    SceneLandmark item;
    item.object_id = object.id;
    relocalization::Landmark& l = item.landmark;
    l.position = object.position;
    l.scale = object.size.norm();
    l.observations = static_cast<uint32_t>(
        std::min<int64_t>(object.detection_count, relocalization::kMaxObservations));
    l.descriptor.assign(dim, 0.0f);
    FillLabelBlock(object, config.labels, l.descriptor.data());
    FillEmbeddingBlock(object.embedding, dim - labels, config.embedding_weight,
                       l.descriptor.data() + labels);
    if (std::none_of(l.descriptor.begin(), l.descriptor.end(), [](float v) { return v != 0.0f; }))
      continue;
    if (!relocalization::ValidateLandmark(l, dim, "landmark").ok()) continue;
    out.push_back(std::move(item));
  }
  return out;
}

std::vector<SceneObject> SettledInstances(const std::vector<SceneObject>& objects,
                                          double settle_s) {
  int64_t newest = std::numeric_limits<int64_t>::min();
  for (const SceneObject& object : objects) newest = std::max(newest, object.last_seen_ns);
  const int64_t settle_ns = static_cast<int64_t>(settle_s * 1e9);
  std::vector<SceneObject> settled;
  for (const SceneObject& object : objects) {
    if (settle_ns == 0 || object.last_seen_ns <= newest - settle_ns) settled.push_back(object);
  }
  return settled;
}

}  // namespace semnav::mapping
