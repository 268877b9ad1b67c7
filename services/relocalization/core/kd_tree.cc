#include "services/relocalization/core/kd_tree.h"

#include <algorithm>
#include <numeric>

namespace semnav::relocalization {

KdTree::KdTree(std::vector<Eigen::Vector3d> points)
    : points_(std::move(points)), order_(points_.size()), axis_(points_.size(), 0) {
  std::iota(order_.begin(), order_.end(), size_t{0});
  Build(0, order_.size());
}

void KdTree::Build(size_t lo, size_t hi) {
  if (hi - lo <= 1) return;
  Eigen::Vector3d min = points_[order_[lo]], max = min;
  for (size_t i = lo + 1; i < hi; ++i) {
    min = min.cwiseMin(points_[order_[i]]);
    max = max.cwiseMax(points_[order_[i]]);
  }
  int axis = 0;
  (max - min).maxCoeff(&axis);
  const size_t mid = (lo + hi) / 2;
  std::nth_element(order_.begin() + static_cast<std::ptrdiff_t>(lo),
                   order_.begin() + static_cast<std::ptrdiff_t>(mid),
                   order_.begin() + static_cast<std::ptrdiff_t>(hi),
                   [&](size_t a, size_t b) { return points_[a][axis] < points_[b][axis]; });
  axis_[mid] = axis;
  Build(lo, mid);
  Build(mid + 1, hi);
}

void KdTree::SearchNearest(size_t lo, size_t hi, const Eigen::Vector3d& q, size_t k,
                           std::vector<Candidate>& heap) const {
  if (lo >= hi) return;
  const size_t mid = (lo + hi) / 2;
  const size_t index = order_[mid];
  const Candidate c{(points_[index] - q).squaredNorm(), index};
  if (heap.size() < k) {
    heap.push_back(c);
    std::push_heap(heap.begin(), heap.end());
  } else if (c < heap.front()) {
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = c;
    std::push_heap(heap.begin(), heap.end());
  }
  const double delta = q[axis_[mid]] - points_[index][axis_[mid]];
  const bool left_first = delta < 0.0;
  SearchNearest(left_first ? lo : mid + 1, left_first ? mid : hi, q, k, heap);
  if (heap.size() < k || delta * delta <= heap.front().distance_sq) {
    SearchNearest(left_first ? mid + 1 : lo, left_first ? hi : mid, q, k, heap);
  }
}

void KdTree::SearchRadius(size_t lo, size_t hi, const Eigen::Vector3d& q, double radius_sq,
                          std::vector<Candidate>& out) const {
  if (lo >= hi) return;
  const size_t mid = (lo + hi) / 2;
  const size_t index = order_[mid];
  const double d2 = (points_[index] - q).squaredNorm();
  if (d2 <= radius_sq) out.push_back({d2, index});
  const double delta = q[axis_[mid]] - points_[index][axis_[mid]];
  if (delta <= 0.0 || delta * delta <= radius_sq) SearchRadius(lo, mid, q, radius_sq, out);
  if (delta >= 0.0 || delta * delta <= radius_sq) SearchRadius(mid + 1, hi, q, radius_sq, out);
}

std::vector<size_t> KdTree::Nearest(const Eigen::Vector3d& query, size_t k) const {
  std::vector<Candidate> heap;
  if (k == 0) return {};
  heap.reserve(k + 1);
  SearchNearest(0, order_.size(), query, k, heap);
  std::sort(heap.begin(), heap.end());
  std::vector<size_t> out;
  out.reserve(heap.size());
  for (const Candidate& c : heap) out.push_back(c.index);
  return out;
}

std::vector<size_t> KdTree::WithinRadius(const Eigen::Vector3d& query, double radius) const {
  std::vector<Candidate> found;
  SearchRadius(0, order_.size(), query, radius * radius, found);
  std::sort(found.begin(), found.end());
  std::vector<size_t> out;
  out.reserve(found.size());
  for (const Candidate& c : found) out.push_back(c.index);
  return out;
}

}  // namespace semnav::relocalization
