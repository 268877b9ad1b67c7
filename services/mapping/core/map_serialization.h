#pragma once

#include <octomap/OcTree.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/mapping/core/scene_types.h"
#include "services/mapping/core/semantic_map.h"

namespace semnav::mapping {

// One hierarchical-grid cell as saved: the Bayesian log-odds and obstacle height the grid
// accumulated over every frame. The octree alone cannot reproduce them (a rebuild applies one
// update per cell), so without these the occupancy layer drifts on load.
struct SavedGridCell {
  int32_t x = 0;
  int32_t y = 0;
  float log_odds = 0.0f;
  uint8_t height = 0;
  bool structure = false;
  bool operator==(const SavedGridCell&) const = default;
};

struct SavedGrid {
  double resolution_m = 0.0;  // the cells are only meaningful at this grid resolution
  std::vector<SavedGridCell> cells;
};

// Everything a stored map holds.
struct MapContent {
  std::unique_ptr<octomap::OcTree> tree;
  std::vector<SceneObject> objects;
  uint64_t next_object_id = 1;
  std::map<std::string, std::vector<Eigen::Vector3f>> semantic_points;
  // Absent in maps saved before the grid was kept: the loader then rebuilds the grid from the
  // octree as before (one update per cell).
  std::optional<SavedGrid> grid;
};

// Payload: length-prefixed sections (8-byte little-endian size each): the OcTree in OctoMap's
// full .ot format (log-odds kept), the scene objects as JSON, the labelled points as JSON, and,
// when `grid` is given, the hierarchical grid: resolution (8-byte IEEE double), cell count
// (8 bytes), then per cell x, y (int32), log-odds (float32), height (uint8), structure (uint8),
// all little-endian. Readers ignore sections they do not know, so older builds still load the
// first three sections of a new file.
std::string SerializeMap(const octomap::OcTree& tree, const std::vector<SceneObject>& objects,
                         uint64_t next_object_id,
                         const std::map<std::string, std::vector<Eigen::Vector3f>>& semantic_points,
                         const SavedGrid* grid = nullptr);

// The same payload from the OcTree already written (OctreeSection). The live snapshot writes the
// tree under the engine's reader lock rather than copying it: a copy of a fleet's map is
// millions of small nodes, freed again every 5 s, and the heap kept their peak.
std::string OctreeSection(const octomap::OcTree& tree);
std::string SerializeMap(std::string octree_section, const std::vector<SceneObject>& objects,
                         uint64_t next_object_id,
                         const std::map<std::string, std::vector<Eigen::Vector3f>>& semantic_points,
                         const SavedGrid* grid = nullptr);

// DATA_LOSS naming what is malformed.
absl::StatusOr<MapContent> ParseMap(const std::string& payload);

}  // namespace semnav::mapping
