#pragma once

#include <string>
#include <vector>

#include "services/mapping/core/scene_types.h"

namespace semnav::mapping {

// Relations between objects whose centres are within near_m (one entry per unordered pair and
// kind, subject = lower id). Map frame, x forward, y left, z up (REP 103):
//   near        always for such pairs;
//   on / above  A's footprint centre inside B's footprint and bottom(A) within on_tolerance_m of
//               top(B) (on) or higher (above);
//   left_of / right_of / in_front_of / behind  by the dominant horizontal axis of A - B when it
//               exceeds direction_margin_m (+y left, +x in front).
std::vector<Relation> ComputeRelations(const std::vector<SceneObject>& objects,
                                       const RelationConfig& config);

// Regions: connected components of "centres within region_radius_m" (seed 002: DBSCAN-like,
// 3 m). Sets each object's region_id. Region ids follow the lowest object id of each region.
std::vector<Region> ComputeRegions(std::vector<SceneObject>& objects, const RelationConfig& config);

// "Scene has N objects in M regions. Region 0 (area_with_chair_desk): 2 chair, 1 desk. ..."
std::string Summarize(const std::vector<SceneObject>& objects, const std::vector<Region>& regions);

}  // namespace semnav::mapping
