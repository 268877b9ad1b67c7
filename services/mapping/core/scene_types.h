#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace semnav::mapping {

// One detection lifted to 3D in the map frame.
struct ObjectObservation {
  std::string label;
  double score = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre, metres
  Eigen::Vector3d size = Eigen::Vector3d::Zero();      // extent along map x, y, z, metres
  std::vector<float> embedding;                        // empty when the detector gave none
  int64_t stamp_ns = 0;
  std::string robot_id;
  bool pose_untrusted = false;  // from a frame whose pose the robot did not trust
};

struct SceneObject {
  uint64_t id = 0;
  std::string label;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  double score = 0.0;  // mean detector score over all detections
  int detection_count = 0;
  // Frames that should have shown it but detected nothing matching (ExistenceConfig); not saved.
  int misses = 0;
  std::vector<float> embedding;  // EMA of the detections' unit embeddings, renormalised
  // Summed detector score per label the instance was detected as; `label` is the best of them,
  // so one confused first detection does not name the instance for good (ConceptGraphs).
  std::map<std::string, double> label_scores;
  int64_t first_seen_ns = 0;
  int64_t last_seen_ns = 0;
  int region_id = -1;
  uint64_t revision = 0;  // graph revision of the object's last change
  // An observation from a frame whose pose the robot did not trust was fused into it, or it was
  // seen shortly before the robot reported the loss: its position may be in the wrong frame, so
  // landmark maps leave it out for good (not saved with the map: a loaded map's landmarks come
  // from its .lmap file, written without such instances).
  bool pose_untrusted = false;
};

enum class RelationKind { kNear, kLeftOf, kRightOf, kInFrontOf, kBehind, kOn, kAbove };

struct Relation {
  uint64_t subject_id = 0;
  RelationKind kind = RelationKind::kNear;
  uint64_t object_id = 0;
  double distance = 0.0;  // centre distance, metres
};

struct Region {
  int id = 0;
  std::string name;  // "area_with_<label>_<label>" from its most frequent labels
  std::vector<uint64_t> object_ids;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
};

// Thresholds of relations and regions (seed 002 names the relations and the 3 m clustering;
// the numeric relation thresholds are ours, documented in docs/algorithms/mapping.md).
struct RelationConfig {
  double near_m = 1.5;              // centre distance for near and for any directional relation
  double direction_margin_m = 0.2;  // a directional relation needs this much offset on its axis
  double on_tolerance_m = 0.15;     // |bottom(A) - top(B)| for A on B
  double region_radius_m = 3.0;     // DBSCAN-like linkage distance of regions
};

}  // namespace semnav::mapping
