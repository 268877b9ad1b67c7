// The gateway's view of mapping's scene graph (seed 002, 3.1.3): objects, pairwise relations
// (near/left_of/right_of/in_front_of/behind/on/above) and 3 m regions. Plain values; the server
// converts mapping's protos into these.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace semnav::reasoning {

struct SceneObject {
  int64_t id = 0;
  std::string label;  // open-vocabulary detector label, e.g. "red cup" or "sofa".
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // map frame, metres.
  double score = 0.0;                                  // detector confidence in [0, 1].
  int detection_count = 0;                             // how many frames confirmed the object.
  int64_t region_id = -1;                              // -1: no region.
  std::vector<std::string> attributes;  // e.g. colours reported by the detector/captioner.
  std::vector<float> embedding;         // visual embedding (CLIP-like); empty: none.
  // Mapping's 10-90 % extent of the seen points along map x, y, z, metres; zero: unknown.
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  // Frames that should have shown the object but did not detect it (mapping's existence evidence,
  // SceneObject.miss_count); only ever grows while the instance lives.
  int miss_count = 0;

  // Largest extent of mapping's box, metres; 0: unknown.
  double scale_m() const { return std::max(size.maxCoeff(), 0.0); }
};

struct SceneRelation {
  int64_t subject_id = 0;
  std::string relation;  // "near", "left_of", ... read as "subject relation object".
  int64_t object_id = 0;
  double distance_m = 0.0;
};

struct SceneRegion {
  int64_t id = 0;
  std::string name;  // e.g. "kitchen" or "area_with_chair_desk".
  std::vector<int64_t> object_ids;
};

struct SceneGraph {
  uint64_t revision = 0;
  std::vector<SceneObject> objects;
  std::vector<SceneRelation> relations;
  std::vector<SceneRegion> regions;

  const SceneObject* FindObject(int64_t id) const;
};

// One empty graph shared by everyone who has none yet.
std::shared_ptr<const SceneGraph> EmptySceneGraph();

}  // namespace semnav::reasoning
