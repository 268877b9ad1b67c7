#include "services/common/geometry/kd_tree.h"

#include <algorithm>
#include <numeric>

namespace semnav::geometry {

template <typename Scalar>
KdTree<Scalar>::KdTree(std::vector<Point> points)
    : points_(std::move(points)), order_(points_.size()), axis_(points_.size(), 0) {
  std::iota(order_.begin(), order_.end(), size_t{0});
  Build(0, order_.size());
  // Store the points in tree layout: queries then walk contiguous memory.
  std::vector<Point> laid_out(points_.size());
  for (size_t slot = 0; slot < order_.size(); ++slot) laid_out[slot] = points_[order_[slot]];
  points_ = std::move(laid_out);
}

template <typename Scalar>
void KdTree<Scalar>::Build(size_t lo, size_t hi) {
  if (hi - lo <= 1) return;
  Point min = points_[order_[lo]], max = min;
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

template <typename Scalar>
void KdTree<Scalar>::SearchNearest(size_t lo, size_t hi, const Point& q, size_t k,
                                   std::vector<Candidate>& heap) const {
  if (lo >= hi) return;
  const size_t mid = (lo + hi) / 2;
  const Candidate c{(points_[mid] - q).squaredNorm(), order_[mid]};
  if (heap.size() < k) {
    heap.push_back(c);
    std::push_heap(heap.begin(), heap.end());
  } else if (c < heap.front()) {
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = c;
    std::push_heap(heap.begin(), heap.end());
  }
  const Scalar delta = q[axis_[mid]] - points_[mid][axis_[mid]];
  const bool left_first = delta < 0;
  SearchNearest(left_first ? lo : mid + 1, left_first ? mid : hi, q, k, heap);
  if (heap.size() < k || delta * delta <= heap.front().distance_sq) {
    SearchNearest(left_first ? mid + 1 : lo, left_first ? hi : mid, q, k, heap);
  }
}

template <typename Scalar>
template <typename Visit>
void KdTree<Scalar>::ForEachWithin(size_t lo, size_t hi, const Point& q, Scalar radius_sq,
                                   Visit& visit) const {
  if (lo >= hi) return;
  const size_t mid = (lo + hi) / 2;
  const Scalar d2 = (points_[mid] - q).squaredNorm();
  if (d2 <= radius_sq) visit(Candidate{d2, order_[mid]});
  // Points left of mid have coordinate <= the node's on its axis, right of mid >=.
  const Scalar delta = q[axis_[mid]] - points_[mid][axis_[mid]];
  if (delta <= 0 || delta * delta <= radius_sq) ForEachWithin(lo, mid, q, radius_sq, visit);
  if (delta >= 0 || delta * delta <= radius_sq) ForEachWithin(mid + 1, hi, q, radius_sq, visit);
}

template <typename Scalar>
std::vector<size_t> KdTree<Scalar>::ClosestFirst(std::vector<Candidate> candidates) {
  std::sort(candidates.begin(), candidates.end());
  std::vector<size_t> out;
  out.reserve(candidates.size());
  for (const Candidate& c : candidates) out.push_back(c.index);
  return out;
}

template <typename Scalar>
std::vector<size_t> KdTree<Scalar>::Nearest(const Point& query, size_t k) const {
  std::vector<Candidate> heap;
  if (k == 0) return {};
  heap.reserve(k + 1);
  SearchNearest(0, order_.size(), query, k, heap);
  return ClosestFirst(std::move(heap));
}

template <typename Scalar>
std::vector<size_t> KdTree<Scalar>::WithinRadius(const Point& query, Scalar radius) const {
  std::vector<Candidate> found;
  auto collect = [&found](const Candidate& c) { found.push_back(c); };
  ForEachWithin(0, order_.size(), query, radius * radius, collect);
  return ClosestFirst(std::move(found));
}

template <typename Scalar>
size_t KdTree<Scalar>::CountCloserThan(const Point& query, Scalar radius) const {
  const Scalar radius_sq = radius * radius;
  size_t count = 0;
  auto count_closer = [&](const Candidate& c) { count += c.distance_sq < radius_sq ? 1 : 0; };
  ForEachWithin(0, order_.size(), query, radius_sq, count_closer);
  return count;
}

template class KdTree<float>;
template class KdTree<double>;

}  // namespace semnav::geometry
