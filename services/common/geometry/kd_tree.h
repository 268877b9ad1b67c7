#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace semnav::geometry {

// Static 3D KD-tree over a point set (median split on the widest axis). Queries return
// indices into the points given to the constructor. Instantiated for float (mapping's point
// clouds) and double (relocalization's landmarks); each query's arithmetic is in Scalar.
template <typename Scalar>
class KdTree {
 public:
  using Point = Eigen::Matrix<Scalar, 3, 1>;

  KdTree() = default;
  explicit KdTree(std::vector<Point> points);

  // Up to k nearest points, closest first (ties by index).
  std::vector<size_t> Nearest(const Point& query, size_t k) const;
  // All points within `radius` (inclusive), closest first.
  std::vector<size_t> WithinRadius(const Point& query, Scalar radius) const;
  // Number of points strictly closer than `radius` (the query point counts if in the set).
  size_t CountCloserThan(const Point& query, Scalar radius) const;

 private:
  struct Candidate {
    Scalar distance_sq;
    size_t index;
    bool operator<(const Candidate& o) const {
      return distance_sq < o.distance_sq || (distance_sq == o.distance_sq && index < o.index);
    }
  };
  // Indices of `candidates`, closest first (ties by index).
  static std::vector<size_t> ClosestFirst(std::vector<Candidate> candidates);
  void Build(size_t lo, size_t hi);
  void SearchNearest(size_t lo, size_t hi, const Point& q, size_t k,
                     std::vector<Candidate>& heap) const;
  // Calls visit(Candidate) for every point with squared distance <= radius_sq.
  template <typename Visit>
  void ForEachWithin(size_t lo, size_t hi, const Point& q, Scalar radius_sq, Visit& visit) const;

  // Tree layout: the node of range [lo, hi) sits at slot (lo + hi) / 2.
  std::vector<Point> points_;  // in input order while building, then in slot order
  std::vector<size_t> order_;  // input index of the point at each slot
  std::vector<int> axis_;      // split axis of the node stored at each slot
};

extern template class KdTree<float>;
extern template class KdTree<double>;

}  // namespace semnav::geometry
