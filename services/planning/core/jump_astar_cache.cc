#include "services/planning/core/jump_astar_cache.h"

#include <algorithm>
#include <utility>

#include "absl/hash/hash.h"
#include "absl/strings/string_view.h"

namespace semnav::planning {
namespace {

size_t ContentHash(const LayeredGrid& grid) {
  const absl::string_view bytes(reinterpret_cast<const char*>(grid.values().data()),
                                grid.values().size());
  return absl::HashOf(grid.width(), grid.height(), bytes);
}

}  // namespace

JumpAStarCache::JumpAStarCache(size_t budget_bytes, RunLater run_later)
    : budget_bytes_(budget_bytes), run_later_(std::move(run_later)) {}

void JumpAStarCache::Evict(uint64_t keep) {
  while (true) {
    size_t total = 0;
    auto oldest = entries_.end();
    for (auto e = entries_.begin(); e != entries_.end(); ++e) {
      total += e->bytes();
      if (e->last_used != keep && (oldest == entries_.end() || e->last_used < oldest->last_used)) {
        oldest = e;
      }
    }
    if (total <= budget_bytes_ || oldest == entries_.end()) return;
    entries_.erase(oldest);
  }
}

JumpAStarCache::Entry* JumpAStarCache::Find(size_t hash, const LayeredGrid& grid,
                                            const StepCosts& costs) {
  for (Entry& e : entries_) {
    const LayeredGrid& cached = e.tables->grid();
    if (e.hash == hash && e.costs == costs && cached.width() == grid.width() &&
        cached.height() == grid.height() && cached.values() == grid.values()) {
      return &e;
    }
  }
  return nullptr;
}

JumpAStarCache::Entry JumpAStarCache::Lookup(size_t hash, const LayeredGrid& grid,
                                             const StepCosts& costs, bool* start_landmarks) {
  {
    absl::MutexLock lock(&mu_);
    if (Entry* e = Find(hash, grid, costs)) {
      e->last_used = ++clock_;
      *start_landmarks = !e->landmarks_requested;
      e->landmarks_requested = true;
      return *e;
    }
  }
  // First query on this grid: build the tables outside the lock.
  auto tables = std::make_shared<const RegionTables>(grid);
  absl::MutexLock lock(&mu_);
  if (Entry* e = Find(hash, grid, costs)) {  // another query built them meanwhile
    e->last_used = ++clock_;
    return *e;
  }
  entries_.push_back({hash, costs, std::move(tables), nullptr, false, ++clock_});
  const Entry added = entries_.back();
  Evict(added.last_used);
  return added;
}

void JumpAStarCache::BuildLandmarks(std::shared_ptr<const RegionTables> tables, StepCosts costs) {
  auto landmarks = std::make_shared<const LandmarkHeuristic>(tables->grid(), costs);
  absl::MutexLock lock(&mu_);
  for (Entry& e : entries_) {
    if (e.tables == tables && e.costs == costs) {
      e.landmarks = landmarks;
      Evict(e.last_used);
      return;
    }
  }
}

std::unique_ptr<JumpAStarPlanner> JumpAStarCache::AcquirePlanner() {
  absl::MutexLock lock(&mu_);
  if (idle_.empty()) return std::make_unique<JumpAStarPlanner>();
  std::unique_ptr<JumpAStarPlanner> planner = std::move(idle_.back());
  idle_.pop_back();
  return planner;
}

void JumpAStarCache::ReleasePlanner(std::unique_ptr<JumpAStarPlanner> planner) {
  absl::MutexLock lock(&mu_);
  idle_.push_back(std::move(planner));
}

absl::StatusOr<MultiModalPath> JumpAStarCache::Plan(const LayeredGrid& grid, Cell start, Cell goal,
                                                    const JumpAStarOptions& options,
                                                    const SearchLimits& limits) {
  std::unique_ptr<JumpAStarPlanner> planner = AcquirePlanner();
  absl::StatusOr<MultiModalPath> path;
  if (absl::Status s = CheckMultiModalEndpoints(grid, start, goal); !s.ok()) {
    path = s;  // no tables for a request that cannot be planned
  } else if (!options.jump_pruning) {
    path = planner->Plan(grid, start, goal, options, limits);
  } else {
    const StepCosts costs = StepCostsOf(options);
    bool start_landmarks = false;
    const Entry entry = Lookup(ContentHash(grid), grid, costs, &start_landmarks);
    if (start_landmarks) {
      run_later_([this, tables = entry.tables, costs] { BuildLandmarks(tables, costs); });
    }
    path = planner->Plan(*entry.tables, entry.landmarks.get(), start, goal, options, limits);
  }
  ReleasePlanner(std::move(planner));
  return path;
}

}  // namespace semnav::planning
