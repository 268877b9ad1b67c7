// The live-map grids planning fetched lately, one per window, so calls that accept a grid of a
// given age (LiveMapGrid.max_age_ms) share one fetch instead of each rendering the live map.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "absl/base/thread_annotations.h"
#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "semnav/common/v1/grid.pb.h"
#include "semnav/planning/v1/grid_source.pb.h"

namespace semnav::planning {

class LiveGridCache {
 public:
  // Keeps the grids of at most `max_windows` windows; the one fetched longest ago goes first.
  explicit LiveGridCache(size_t max_windows = 8) : max_windows_(max_windows) {}

  // The grid of `live`'s window fetched at or after now - max_age (the newest one); null when
  // there is none or max_age is zero.
  std::shared_ptr<const semnav::common::v1::GridMap> Find(
      const semnav::planning::v1::LiveMapGrid& live, absl::Time now, absl::Duration max_age)
      ABSL_LOCKS_EXCLUDED(mu_);
  // Keeps `grid` as `live`'s window fetched at `fetched_at`, unless a later fetch is kept already.
  void Put(const semnav::planning::v1::LiveMapGrid& live,
           std::shared_ptr<const semnav::common::v1::GridMap> grid, absl::Time fetched_at)
      ABSL_LOCKS_EXCLUDED(mu_);
  // Refresh ahead: true when `live`'s window keeps a grid fetched before now - refresh_after and
  // no refresh of it is running; the caller then fetches it again off the call's path and ends
  // with Put, or with EndRefresh when the fetch failed. Calls that accept the kept grid's age go
  // on using it meanwhile, so a steady stream of calls never waits for a fetch.
  bool ClaimRefresh(const semnav::planning::v1::LiveMapGrid& live, absl::Time now,
                    absl::Duration refresh_after) ABSL_LOCKS_EXCLUDED(mu_);
  void EndRefresh(const semnav::planning::v1::LiveMapGrid& live) ABSL_LOCKS_EXCLUDED(mu_);

 private:
  struct Window {
    bool whole = true;  // no window: the whole live map
    double min_x = 0, min_y = 0, max_x = 0, max_y = 0;
    bool operator==(const Window&) const = default;
  };
  struct Entry {
    Window window;
    absl::Time fetched_at;
    std::shared_ptr<const semnav::common::v1::GridMap> grid;
    bool refreshing = false;  // ClaimRefresh answered true; Put or EndRefresh not yet called
  };
  static Window WindowOf(const semnav::planning::v1::LiveMapGrid& live);
  // The entry of `window` (one per window), or null.
  Entry* EntryOf(const Window& window) ABSL_EXCLUSIVE_LOCKS_REQUIRED(mu_);

  const size_t max_windows_;
  absl::Mutex mu_;
  std::vector<Entry> entries_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::planning
