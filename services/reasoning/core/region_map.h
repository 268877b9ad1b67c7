// Open-vocabulary semantic map with region-unit LLM scoring (seed 000, 2.1.4, Algorithm 2): every
// <position, description> pair is stored; EROIs are merged into region units of `region_size`^3
// EROIs (the map g); when a unit has collected theta = 3 new descriptions it is due for scoring.
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/reasoning/core/eroi_grid.h"

namespace semnav::reasoning {

struct RegionMapConfig {
  int region_size = 2;  // EROIs per axis merged into one region unit (g: P_E -> R).
  int theta = 3;        // observations per unit that trigger an LLM score (seed: N = 3).
};

struct RegionDue {
  int region = 0;                         // region unit id
  std::vector<int> erois;                 // flat EROI indices of the unit (k = size)
  std::vector<std::string> descriptions;  // all descriptions recorded in the unit (P*_rn)
};

class RegionMap {
 public:
  RegionMap(const EroiGrid* grid, RegionMapConfig config);

  // Algorithm 2 step 2-3: records the pair; returns the unit when U(r) reached theta (and resets
  // U(r) to 0). NOT_FOUND if `position` is outside the grid.
  absl::StatusOr<std::optional<RegionDue>> Add(const Eigen::Vector3d& position,
                                               std::string description);

  int RegionOf(int eroi) const;
  // M: descriptions per EROI centre.
  const std::map<int, std::vector<std::string>>& descriptions() const { return descriptions_; }

 private:
  const EroiGrid* grid_;
  RegionMapConfig config_;
  std::map<int, std::vector<std::string>> descriptions_;
  std::map<int, int> pending_;  // U(r)
};

}  // namespace semnav::reasoning
