#include "services/mapping/core/kd_tree.h"

#include <algorithm>

namespace semnav::mapping {

KdTree::KdTree(const std::vector<Eigen::Vector3f>& points) : points_(points) { Build(0, points_.size(), 0); }

void KdTree::Build(size_t begin, size_t end, int depth) {
  if (end - begin <= 1) return;
  const int axis = depth % 3;
  const size_t mid = begin + (end - begin) / 2;
  std::nth_element(points_.begin() + static_cast<std::ptrdiff_t>(begin), points_.begin() + static_cast<std::ptrdiff_t>(mid),
                   points_.begin() + static_cast<std::ptrdiff_t>(end),
                   [axis](const Eigen::Vector3f& a, const Eigen::Vector3f& b) { return a[axis] < b[axis]; });
  Build(begin, mid, depth + 1);
  Build(mid + 1, end, depth + 1);
}

size_t KdTree::CountWithin(const Eigen::Vector3f& query, float radius) const {
  return Count(0, points_.size(), 0, query, radius * radius);
}

size_t KdTree::Count(size_t begin, size_t end, int depth, const Eigen::Vector3f& query, float radius_sq) const {
  if (begin >= end) return 0;
  const int axis = depth % 3;
  const size_t mid = begin + (end - begin) / 2;
  const Eigen::Vector3f& p = points_[mid];
  size_t count = (p - query).squaredNorm() < radius_sq ? 1 : 0;
  const float delta = query[axis] - p[axis];
  // Points left of mid have coordinate <= p[axis], right of mid >= p[axis].
  if (delta <= 0.0f || delta * delta < radius_sq) count += Count(begin, mid, depth + 1, query, radius_sq);
  if (delta >= 0.0f || delta * delta < radius_sq) count += Count(mid + 1, end, depth + 1, query, radius_sq);
  return count;
}

}  // namespace semnav::mapping
