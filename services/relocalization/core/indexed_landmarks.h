#pragma once

#include <unordered_map>
#include <vector>

#include "services/common/geometry/kd_tree.h"
#include "services/relocalization/core/landmark.h"

namespace semnav::relocalization {

// An immutable landmark set with the two indexes of seed 001, 3.1: a hash table keyed
// by each landmark's most similar label, and a KD-tree over positions for neighbourhoods.
class IndexedLandmarks {
 public:
  IndexedLandmarks() = default;
  explicit IndexedLandmarks(std::vector<Landmark> landmarks);

  const std::vector<Landmark>& landmarks() const { return landmarks_; }
  const Landmark& at(size_t i) const { return landmarks_[i]; }
  size_t size() const { return landmarks_.size(); }
  bool empty() const { return landmarks_.empty(); }
  int label(size_t i) const { return labels_[i]; }

  // H(L): landmarks whose most similar label is `label` (empty when none).
  const std::vector<size_t>& WithLabel(int label) const;
  // Cosine similarity of landmark i's descriptor with a unit-normalised descriptor.
  double DescriptorSimilarity(size_t i, const std::vector<float>& unit_descriptor) const;
  const std::vector<float>& unit_descriptor(size_t i) const { return unit_descriptors_[i]; }

  // Whether another landmark within `radius_m` of landmark i has the same label and a
  // descriptor cosine >= `min_cosine` to it: a look-alike twin (a box beside a box on a shelf).
  bool HasLookalikeWithin(size_t i, double radius_m, double min_cosine) const;

  // N(P): up to k nearest other landmarks of landmark i, closest first.
  std::vector<size_t> Neighbourhood(size_t i, size_t k) const;
  const geometry::KdTree<double>& tree() const { return tree_; }

 private:
  std::vector<Landmark> landmarks_;
  std::vector<int> labels_;
  std::vector<std::vector<float>> unit_descriptors_;
  std::unordered_map<int, std::vector<size_t>> by_label_;
  geometry::KdTree<double> tree_;
};

// The descriptor scaled to unit length (all zeros stays all zeros).
std::vector<float> UnitDescriptor(const Descriptor& descriptor);

}  // namespace semnav::relocalization
