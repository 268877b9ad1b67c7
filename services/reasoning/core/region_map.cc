#include "services/reasoning/core/region_map.h"

#include <algorithm>

namespace semnav::reasoning {

RegionMap::RegionMap(const EroiGrid* grid, RegionMapConfig config) : grid_(grid), config_(config) {
  config_.region_size = std::max(1, config_.region_size);
  config_.theta = std::max(1, config_.theta);
}

int RegionMap::RegionOf(int eroi) const {
  const EroiIndex index = grid_->Unflatten(eroi);
  const EroiGridSpec& spec = grid_->spec();
  const int size = config_.region_size;
  const int rx = spec.nx / size + 1;
  const int ry = spec.ny / size + 1;
  return ((index.k / size) * ry + index.j / size) * rx + index.i / size;
}

absl::StatusOr<std::optional<RegionDue>> RegionMap::Add(const Eigen::Vector3d& position,
                                                        std::string description) {
  absl::StatusOr<EroiIndex> index = grid_->Locate(position);
  if (!index.ok()) return index.status();
  const int eroi = grid_->Flatten(*index);
  descriptions_[eroi].push_back(std::move(description));
  const int region = RegionOf(eroi);
  if (++pending_[region] < config_.theta) return std::optional<RegionDue>();
  pending_[region] = 0;
  RegionDue due;
  due.region = region;
  for (int flat = 0; flat < grid_->size(); ++flat) {
    if (RegionOf(flat) != region) continue;
    due.erois.push_back(flat);
    auto it = descriptions_.find(flat);
    if (it != descriptions_.end()) {
      due.descriptions.insert(due.descriptions.end(), it->second.begin(), it->second.end());
    }
  }
  return std::optional<RegionDue>(std::move(due));
}

}  // namespace semnav::reasoning
