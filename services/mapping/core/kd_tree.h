#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace semnav::mapping {

// Static 3D KD-tree over a point set (median split, implicit layout): radius counting for the
// semantic point-cloud filter of seed 004.
class KdTree {
 public:
  explicit KdTree(const std::vector<Eigen::Vector3f>& points);

  // Number of points p' with |p' - query| < radius (the query point itself counts if it is in the set).
  size_t CountWithin(const Eigen::Vector3f& query, float radius) const;

 private:
  void Build(size_t begin, size_t end, int depth);
  size_t Count(size_t begin, size_t end, int depth, const Eigen::Vector3f& query, float radius_sq) const;

  std::vector<Eigen::Vector3f> points_;  // reordered so each [begin, end) range has its median at the middle
};

}  // namespace semnav::mapping
