#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

namespace semnav::relocalization {

// Static 3D KD-tree over a point set (median split on the widest axis).
// Queries return indices into the points given to the constructor.
class KdTree {
 public:
  KdTree() = default;
  explicit KdTree(std::vector<Eigen::Vector3d> points);

  // Up to k nearest points, closest first (ties by index).
  std::vector<size_t> Nearest(const Eigen::Vector3d& query, size_t k) const;
  // All points within `radius` (inclusive), closest first.
  std::vector<size_t> WithinRadius(const Eigen::Vector3d& query, double radius) const;

 private:
  struct Candidate {
    double distance_sq;
    size_t index;
    bool operator<(const Candidate& o) const {
      return distance_sq < o.distance_sq || (distance_sq == o.distance_sq && index < o.index);
    }
  };
  void Build(size_t lo, size_t hi);
  void SearchNearest(size_t lo, size_t hi, const Eigen::Vector3d& q, size_t k,
                     std::vector<Candidate>& heap) const;
  void SearchRadius(size_t lo, size_t hi, const Eigen::Vector3d& q, double radius_sq,
                    std::vector<Candidate>& out) const;

  std::vector<Eigen::Vector3d> points_;
  std::vector<size_t> order_;  // tree layout: node of range [lo, hi) sits at (lo + hi) / 2
  std::vector<int> axis_;      // split axis of the node stored at each slot
};

}  // namespace semnav::relocalization
