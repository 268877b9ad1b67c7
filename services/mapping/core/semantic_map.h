#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "absl/container/flat_hash_set.h"
#include "services/mapping/core/grid_layers.h"

namespace semnav::mapping {

struct SemanticMapConfig {
  double point_resolution_m = 0.02;  // labelled points are kept once per cube of this size
  float radius_m = 0.1f;             // seed 004 KD-tree filter radius
  int min_neighbours = 5;            // seed 004: keep when more than 5 same-label neighbours
  int opening_kernel = 3;            // seed 004 opening of the 2D semantic map
};

// Labelled 3D points (from eroded detection masks) and the 2D semantic layer made from them
// with the seed-004 KD-tree radius filter and opening.
class SemanticMap {
 public:
  explicit SemanticMap(const SemanticMapConfig& config) : config_(config) {}

  void Add(const std::string& label, const std::vector<Eigen::Vector3f>& points);
  // Fills layers.semantic / semantic_labels for the layers' window: per label, points that pass
  // the radius filter mark their cell, the label's cell map is opened, then written with index
  // = position of the label in sorted order + 1 (later labels win shared cells).
  void Render(GridLayers& layers) const;

  const std::map<std::string, std::vector<Eigen::Vector3f>>& points() const { return points_; }
  void Clear();

 private:
  SemanticMapConfig config_;
  std::map<std::string, std::vector<Eigen::Vector3f>> points_;
  std::map<std::string, absl::flat_hash_set<std::array<int, 3>>> occupied_cubes_;
};

}  // namespace semnav::mapping
