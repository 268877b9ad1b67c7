#include "services/planning/server/footprint_cache.h"

#include <algorithm>

namespace semnav::planning {

std::shared_ptr<const PreparedFootprint> FootprintCache::Get(
    const std::shared_ptr<const semnav::common::v1::GridMap>& grid, double robot_radius_m,
    bool keep_clearance, absl::FunctionRef<PreparedFootprint()> prepare) {
  if (grid.use_count() == 0 || max_entries_ == 0) {
    return std::make_shared<const PreparedFootprint>(prepare());
  }
  // An expired entry never matches: its grid is gone, even if a new one took its address.
  const auto same = [&](const Entry& e) {
    return e.robot_radius_m == robot_radius_m && e.keep_clearance == keep_clearance &&
           e.grid.lock() == grid;
  };
  {
    absl::MutexLock lock(&mu_);
    std::erase_if(entries_, [](const Entry& e) { return e.grid.expired(); });
    auto kept = std::find_if(entries_.begin(), entries_.end(), same);
    if (kept != entries_.end()) {
      kept->last_used = ++uses_;
      return kept->footprint;
    }
  }
  // Prepared outside the lock: two calls may both prepare it, and the first kept wins.
  auto footprint = std::make_shared<const PreparedFootprint>(prepare());
  absl::MutexLock lock(&mu_);
  auto kept = std::find_if(entries_.begin(), entries_.end(), same);
  if (kept != entries_.end()) return kept->footprint;
  if (entries_.size() >= max_entries_) {
    entries_.erase(
        std::min_element(entries_.begin(), entries_.end(),
                         [](const Entry& a, const Entry& b) { return a.last_used < b.last_used; }));
  }
  entries_.push_back(Entry{grid, robot_radius_m, keep_clearance, footprint, ++uses_});
  return footprint;
}

}  // namespace semnav::planning
