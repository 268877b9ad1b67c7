#pragma once

#include <memory>
#include <string>
#include <vector>

#include <octomap/OcTree.h>

#include "absl/status/statusor.h"
#include "services/mapping/core/scene_types.h"
#include "services/mapping/core/semantic_map.h"

namespace semnav::mapping {

// Everything a stored map holds. The grid is rebuilt from the octree on load.
struct MapContent {
  std::unique_ptr<octomap::OcTree> tree;
  std::vector<SceneObject> objects;
  uint64_t next_object_id = 1;
  std::map<std::string, std::vector<Eigen::Vector3f>> semantic_points;
};

// Payload: three length-prefixed sections (8-byte little-endian size each): the OcTree in
// OctoMap's full .ot format (log-odds kept), the scene objects as JSON, the labelled points as JSON.
std::string SerializeMap(const octomap::OcTree& tree, const std::vector<SceneObject>& objects, uint64_t next_object_id,
                         const std::map<std::string, std::vector<Eigen::Vector3f>>& semantic_points);

// DATA_LOSS naming what is malformed.
absl::StatusOr<MapContent> ParseMap(const std::string& payload);

}  // namespace semnav::mapping
