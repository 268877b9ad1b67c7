#pragma once

#include <Eigen/Core>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "absl/functional/function_ref.h"
#include "services/mapping/core/grid_layers.h"

namespace semnav::mapping {

struct SemanticMapConfig {
  double point_resolution_m = 0.02;  // labelled points are kept once per cube of this size
  float radius_m = 0.1f;             // seed 004 KD-tree filter radius
  int min_neighbours = 5;            // seed 004: keep when more than 5 same-label neighbours
  int opening_kernel = 3;            // seed 004 opening of the 2D semantic map
  // Per label, at most max_points_per_voxel points in each cap_voxel_m cube. Depth noise keeps
  // landing in new point cubes around a surface, so without a cap the points grow with every
  // frame (the fleet bench's mapping RSS grew ~20 % in 4 min). The cap voxel is the grid cell
  // (0.05 m), so every cell a surface covers keeps points; 4 of the 27 possible point cubes
  // leave real surfaces far above the radius filter's min_neighbours.
  double cap_voxel_m = 0.05;
  int max_points_per_voxel = 4;
  // Stray points: depth noise still lands in ever new cap voxels around surfaces (the fleet bench:
  // 100k -> 181k points in 90 s with 50 robots, mostly points the radius filter rejects). When a
  // label's points reach prune_growth times the number that passed the radius filter at its last
  // prune (and at least prune_min_points), the points that fail the filter and were already there
  // at the last prune are dropped: each point gets one whole interval to gather neighbours. A
  // label's points stay below max(prune_min_points, prune_growth x passing) plus one frame.
  double prune_growth = 2.0;
  int prune_min_points = 4096;
  // A labelled point lives as long as a scene-graph instance carrying its label (in its label
  // scores) holds it within its fused box grown by this margin: the points of an instance the scene
  // graph removed (a false detection, one the detector keeps missing) go with it. Without this
  // every false detection's patch stayed for good, and the fleet bench's mapping RSS kept
  // growing after its scene graph had settled (docs/performance.md). Negative = keep all points.
  double instance_support_margin_m = 0.25;
  // ... and whose label is the point's, or gives it at least this share of its summed votes.
  double instance_support_min_share = 0.25;
};

// Labelled 3D points (from eroded detection masks) and the 2D semantic layer made from them
// with the seed-004 KD-tree radius filter and opening.
class SemanticMap {
 public:
  explicit SemanticMap(const SemanticMapConfig& config) : config_(config) {}

  using SupportFn = absl::FunctionRef<bool(const std::string& label, const Eigen::Vector3f& point)>;

  // Adds a detection's points. When the label's points are due for a prune, the prune also drops
  // the points `supported` rejects (instance support); without it every point is supported.
  void Add(const std::string& label, const std::vector<Eigen::Vector3f>& points,
           SupportFn supported);
  void Add(const std::string& label, const std::vector<Eigen::Vector3f>& points);
  // Fills layers.semantic / semantic_labels for the layers' window: per label, points that pass
  // the radius filter mark their cell, the label's cell map is opened, then written with index
  // = position of the label in sorted order + 1 (later labels win shared cells).
  void Render(GridLayers& layers) const;

  const std::map<std::string, std::vector<Eigen::Vector3f>>& points() const { return points_; }
  void Clear();
  // Drops the points of `labels` that `supported(label, point)` rejects; a label left without
  // points is forgotten. Returns how many points went.
  size_t KeepSupported(const std::set<std::string>& labels, SupportFn supported);

 private:
  SemanticMapConfig config_;
  std::map<std::string, std::vector<Eigen::Vector3f>> points_;
  std::map<std::string, absl::flat_hash_set<std::array<int, 3>>> occupied_cubes_;
  std::map<std::string, absl::flat_hash_map<std::array<int, 3>, int>> points_per_voxel_;
  // Per label, at its last prune: the points kept (the older ones, at the front of points_) and
  // how many of them passed the radius filter.
  struct PruneState {
    size_t kept = 0;
    size_t passing = 0;
  };
  std::map<std::string, PruneState> last_prune_;

  // Drops the label's points that fail the radius filter and are older than its last prune, and
  // those `supported` rejects.
  void Prune(const std::string& label, SupportFn supported);
  // Drops everything of the label.
  void Forget(const std::string& label);
  // Rebuilds the label's cube and cap-voxel counts from its points.
  void Reindex(const std::string& label);
};

}  // namespace semnav::mapping
