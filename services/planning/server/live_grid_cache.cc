#include "services/planning/server/live_grid_cache.h"

#include <algorithm>

namespace semnav::planning {

LiveGridCache::Window LiveGridCache::WindowOf(const semnav::planning::v1::LiveMapGrid& live) {
  // FetchLiveGrid asks for a window when either corner is set.
  if (!live.has_window_min() && !live.has_window_max()) return Window{};
  return Window{false, live.window_min().x(), live.window_min().y(), live.window_max().x(),
                live.window_max().y()};
}

LiveGridCache::Entry* LiveGridCache::EntryOf(const Window& window) {
  auto same = std::find_if(entries_.begin(), entries_.end(),
                           [&](const Entry& e) { return e.window == window; });
  return same == entries_.end() ? nullptr : &*same;
}

std::shared_ptr<const semnav::common::v1::GridMap> LiveGridCache::Find(
    const semnav::planning::v1::LiveMapGrid& live, absl::Time now, absl::Duration max_age) {
  if (max_age <= absl::ZeroDuration()) return nullptr;
  const Window window = WindowOf(live);
  absl::MutexLock lock(&mu_);
  const Entry* entry = EntryOf(window);
  // A fetch stamped after `now` (another worker's, just finished) is fresher still.
  return entry != nullptr && now - entry->fetched_at <= max_age ? entry->grid : nullptr;
}

void LiveGridCache::Put(const semnav::planning::v1::LiveMapGrid& live,
                        std::shared_ptr<const semnav::common::v1::GridMap> grid,
                        absl::Time fetched_at) {
  if (max_windows_ == 0) return;
  const Window window = WindowOf(live);
  absl::MutexLock lock(&mu_);
  if (Entry* same = EntryOf(window)) {
    same->refreshing = false;
    if (same->fetched_at > fetched_at) return;
    same->fetched_at = fetched_at;
    same->grid = std::move(grid);
    return;
  }
  if (entries_.size() >= max_windows_) {
    entries_.erase(std::min_element(
        entries_.begin(), entries_.end(),
        [](const Entry& a, const Entry& b) { return a.fetched_at < b.fetched_at; }));
  }
  entries_.push_back(Entry{window, fetched_at, std::move(grid)});
}

bool LiveGridCache::ClaimRefresh(const semnav::planning::v1::LiveMapGrid& live, absl::Time now,
                                 absl::Duration refresh_after) {
  const Window window = WindowOf(live);
  absl::MutexLock lock(&mu_);
  Entry* entry = EntryOf(window);
  if (entry == nullptr || entry->refreshing || now - entry->fetched_at <= refresh_after) {
    return false;
  }
  entry->refreshing = true;
  return true;
}

void LiveGridCache::EndRefresh(const semnav::planning::v1::LiveMapGrid& live) {
  const Window window = WindowOf(live);
  absl::MutexLock lock(&mu_);
  if (Entry* entry = EntryOf(window)) entry->refreshing = false;
}

}  // namespace semnav::planning
