#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/synchronization/mutex.h"
#include "services/planning/core/jump_astar.h"

namespace semnav::planning {

// Per-map state of the improved Jump A* kept across queries, so the
// preprocessing is paid once per map rather than per request:
//  - 1st query on a grid: builds its region tables (cold), plans with the
//    octile bound, keeps the tables;
//  - 2nd query: reuses the tables and hands the landmark build (4
//    whole-grid Dijkstras) to `run_later`, off the query path; a grid
//    queried once never pays for landmarks;
//  - later queries: tables + landmark bound (the warm case).
// Keyed by the grid content (hash, confirmed by a full compare) and the
// step costs, so inline grids and live maps are treated alike and a changed
// map is a new entry; least recently used entries are dropped while the
// cache holds more than `budget_bytes` (the newest entry always stays). Results are exactly those
// of JumpAStarPlanner. Thread-safe.
class JumpAStarCache {
 public:
  using RunLater = std::function<void(std::function<void()>)>;

  // run_later must run every job it accepts before the cache is destroyed.
  JumpAStarCache(size_t budget_bytes, RunLater run_later);

  absl::StatusOr<MultiModalPath> Plan(const LayeredGrid& grid, Cell start, Cell goal,
                                      const JumpAStarOptions& options,
                                      const SearchLimits& limits = {});

 private:
  struct Entry {
    size_t hash = 0;
    StepCosts costs;
    std::shared_ptr<const RegionTables> tables;
    std::shared_ptr<const LandmarkHeuristic> landmarks;  // null until built
    bool landmarks_requested = false;
    uint64_t last_used = 0;  // unique: the cache clock at the last use
    size_t bytes() const { return tables->bytes() + (landmarks ? landmarks->bytes() : 0); }
  };

  // The entry for this grid and costs, or null.
  Entry* Find(size_t hash, const LayeredGrid& grid, const StepCosts& costs)
      ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Drops least recently used entries, except the one last used at `keep`,
  // while over budget.
  void Evict(uint64_t keep) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);
  // Finds or adds the entry; copies out what the query needs and whether
  // the landmark build should start now.
  Entry Lookup(size_t hash, const LayeredGrid& grid, const StepCosts& costs, bool* start_landmarks);
  void BuildLandmarks(std::shared_ptr<const RegionTables> tables, StepCosts costs);
  std::unique_ptr<JumpAStarPlanner> AcquirePlanner();
  void ReleasePlanner(std::unique_ptr<JumpAStarPlanner> planner);

  const size_t budget_bytes_;
  const RunLater run_later_;
  absl::Mutex mu_;
  std::vector<Entry> entries_ ABSL_GUARDED_BY(mu_);
  uint64_t clock_ ABSL_GUARDED_BY(mu_) = 0;
  // Idle planners (search workspaces), one per concurrent query at most.
  std::vector<std::unique_ptr<JumpAStarPlanner>> idle_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::planning
