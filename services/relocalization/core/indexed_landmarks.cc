#include "services/relocalization/core/indexed_landmarks.h"

#include <algorithm>
#include <cmath>

namespace semnav::relocalization {
namespace {

std::vector<Eigen::Vector3d> Positions(const std::vector<Landmark>& landmarks) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(landmarks.size());
  for (const Landmark& l : landmarks) out.push_back(l.position);
  return out;
}

}  // namespace

std::vector<float> UnitDescriptor(const Descriptor& descriptor) {
  double norm_sq = 0.0;
  for (float v : descriptor) norm_sq += static_cast<double>(v) * v;
  std::vector<float> out(descriptor.size(), 0.0f);
  if (norm_sq <= 0.0) return out;
  const double inv = 1.0 / std::sqrt(norm_sq);
  for (size_t i = 0; i < descriptor.size(); ++i) out[i] = static_cast<float>(descriptor[i] * inv);
  return out;
}

IndexedLandmarks::IndexedLandmarks(std::vector<Landmark> landmarks)
    : landmarks_(std::move(landmarks)), tree_(Positions(landmarks_)) {
  labels_.reserve(landmarks_.size());
  unit_descriptors_.reserve(landmarks_.size());
  for (size_t i = 0; i < landmarks_.size(); ++i) {
    labels_.push_back(DescriptorLabel(landmarks_[i].descriptor));
    unit_descriptors_.push_back(UnitDescriptor(landmarks_[i].descriptor));
    by_label_[labels_.back()].push_back(i);
  }
}

const std::vector<size_t>& IndexedLandmarks::WithLabel(int label) const {
  static const std::vector<size_t> kNone;
  const auto it = by_label_.find(label);
  return it == by_label_.end() ? kNone : it->second;
}

double IndexedLandmarks::DescriptorSimilarity(size_t i,
                                              const std::vector<float>& unit_descriptor) const {
  const std::vector<float>& mine = unit_descriptors_[i];
  const Eigen::Index n = static_cast<Eigen::Index>(std::min(mine.size(), unit_descriptor.size()));
  // Eigen's vectorised reduction; this dot product dominates retrieval time.
  return Eigen::Map<const Eigen::VectorXf>(mine.data(), n)
      .dot(Eigen::Map<const Eigen::VectorXf>(unit_descriptor.data(), n));
}

bool IndexedLandmarks::HasLookalikeWithin(size_t i, double radius_m, double min_cosine) const {
  for (size_t j : tree_.WithinRadius(landmarks_[i].position, radius_m)) {
    if (j != i && labels_[j] == labels_[i] &&
        DescriptorSimilarity(j, unit_descriptors_[i]) >= min_cosine) {
      return true;
    }
  }
  return false;
}

std::vector<size_t> IndexedLandmarks::Neighbourhood(size_t i, size_t k) const {
  std::vector<size_t> nearest = tree_.Nearest(landmarks_[i].position, k + 1);
  std::erase(nearest, i);
  if (nearest.size() > k) nearest.resize(k);
  return nearest;
}

}  // namespace semnav::relocalization
