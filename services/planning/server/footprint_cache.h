// The footprint work (inflation, clearance cost) of the grids planning keeps, per footprint, so
// the PlanPath calls on one kept live grid inflate and cost it once instead of once each.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/functional/function_ref.h"
#include "absl/synchronization/mutex.h"
#include "semnav/common/v1/grid.pb.h"
#include "services/planning/core/grid_planner.h"

namespace semnav::planning {

class FootprintCache {
 public:
  // Keeps the footprints of at most `max_entries` (grid, radius, clearance) triples; the one
  // used longest ago goes first, and a footprint goes with its grid: entries only watch their
  // grid (weak_ptr), so the cache never keeps a grid the live-grid cache has let go.
  explicit FootprintCache(size_t max_entries = 8) : max_entries_(max_entries) {}

  // The footprint of `grid` for (robot_radius_m, keep_clearance): the kept one, or `prepare()`'s,
  // then kept. A grid nobody owns (a request's inline grid) is prepared and not kept.
  std::shared_ptr<const PreparedFootprint> Get(
      const std::shared_ptr<const semnav::common::v1::GridMap>& grid, double robot_radius_m,
      bool keep_clearance, absl::FunctionRef<PreparedFootprint()> prepare) ABSL_LOCKS_EXCLUDED(mu_);

 private:
  struct Entry {
    std::weak_ptr<const semnav::common::v1::GridMap> grid;
    double robot_radius_m = 0.0;
    bool keep_clearance = false;
    std::shared_ptr<const PreparedFootprint> footprint;
    uint64_t last_used = 0;
  };

  const size_t max_entries_;
  absl::Mutex mu_;
  std::vector<Entry> entries_ ABSL_GUARDED_BY(mu_);
  uint64_t uses_ ABSL_GUARDED_BY(mu_) = 0;
};

}  // namespace semnav::planning
