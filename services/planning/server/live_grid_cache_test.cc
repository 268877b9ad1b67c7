// LiveGridCache: which kept grid a call of a given accepted age gets, per window.
#include "services/planning/server/live_grid_cache.h"

#include "gtest/gtest.h"

namespace semnav::planning {
namespace {

using semnav::common::v1::GridMap;
using semnav::planning::v1::LiveMapGrid;

std::shared_ptr<const GridMap> GridOfRevision(uint64_t revision) {
  auto grid = std::make_shared<GridMap>();
  grid->set_revision(revision);
  return grid;
}

// The revision of the grid Find answers; 0 = none (gtest would print a found GridMap whole).
uint64_t Found(LiveGridCache& cache, const LiveMapGrid& live, absl::Time now,
               absl::Duration max_age) {
  std::shared_ptr<const GridMap> grid = cache.Find(live, now, max_age);
  return grid == nullptr ? 0 : grid->revision();
}

LiveMapGrid Window(double min_x, double max_x) {
  LiveMapGrid live;
  live.mutable_window_min()->set_x(min_x);
  live.mutable_window_max()->set_x(max_x);
  live.mutable_window_max()->set_y(4.0);
  return live;
}

TEST(LiveGridCache, AGridIsFoundWhileItIsNoOlderThanTheAcceptedAge) {
  LiveGridCache cache;
  const absl::Time t0 = absl::FromUnixSeconds(1000);
  const LiveMapGrid whole;
  EXPECT_EQ(Found(cache, whole, t0, absl::Seconds(1)), 0u);  // nothing kept yet
  cache.Put(whole, GridOfRevision(7), t0);
  EXPECT_EQ(Found(cache, whole, t0 + absl::Milliseconds(500), absl::Milliseconds(500)), 7u);
  EXPECT_EQ(Found(cache, whole, t0 + absl::Milliseconds(501), absl::Milliseconds(500)), 0u);
  EXPECT_EQ(Found(cache, whole, t0, absl::ZeroDuration()), 0u);  // 0 = fetch now
}

TEST(LiveGridCache, EachWindowKeepsItsOwnGridAndALaterFetchWins) {
  LiveGridCache cache;
  const absl::Time t0 = absl::FromUnixSeconds(1000);
  const LiveMapGrid whole;
  cache.Put(whole, GridOfRevision(7), t0);
  cache.Put(Window(0.0, 8.0), GridOfRevision(8), t0);
  EXPECT_EQ(Found(cache, whole, t0, absl::Seconds(1)), 7u);
  EXPECT_EQ(Found(cache, Window(0.0, 8.0), t0, absl::Seconds(1)), 8u);
  EXPECT_EQ(Found(cache, Window(0.0, 9.0), t0, absl::Seconds(1)), 0u);
  // A fetch that finishes after a later one does not replace it.
  cache.Put(whole, GridOfRevision(9), t0 + absl::Milliseconds(100));
  cache.Put(whole, GridOfRevision(8), t0 + absl::Milliseconds(50));
  EXPECT_EQ(Found(cache, whole, t0 + absl::Milliseconds(100), absl::Seconds(1)), 9u);
}

TEST(LiveGridCache, TheWindowFetchedLongestAgoGoesFirst) {
  LiveGridCache cache(2);
  const absl::Time t0 = absl::FromUnixSeconds(1000);
  cache.Put(Window(0.0, 1.0), GridOfRevision(1), t0);
  cache.Put(Window(0.0, 2.0), GridOfRevision(2), t0 + absl::Milliseconds(10));
  cache.Put(Window(0.0, 3.0), GridOfRevision(3), t0 + absl::Milliseconds(20));
  const absl::Time now = t0 + absl::Milliseconds(30);
  EXPECT_EQ(Found(cache, Window(0.0, 1.0), now, absl::Seconds(1)), 0u);
  EXPECT_EQ(Found(cache, Window(0.0, 2.0), now, absl::Seconds(1)), 2u);
  EXPECT_EQ(Found(cache, Window(0.0, 3.0), now, absl::Seconds(1)), 3u);
}

TEST(LiveGridCache, ARefreshIsClaimedOnceAfterHalfTheAgeAndEndsWithPutOrEndRefresh) {
  LiveGridCache cache;
  const absl::Time t0 = absl::FromUnixSeconds(1000);
  const LiveMapGrid whole;
  const absl::Duration after = absl::Milliseconds(250);
  EXPECT_FALSE(cache.ClaimRefresh(whole, t0, after));  // nothing kept: the call fetches itself
  cache.Put(whole, GridOfRevision(7), t0);
  EXPECT_FALSE(cache.ClaimRefresh(whole, t0 + absl::Milliseconds(250), after));  // still fresh
  EXPECT_TRUE(cache.ClaimRefresh(whole, t0 + absl::Milliseconds(251), after));
  EXPECT_FALSE(cache.ClaimRefresh(whole, t0 + absl::Milliseconds(300), after));  // one at a time
  EXPECT_FALSE(cache.ClaimRefresh(Window(0.0, 5.0), t0 + absl::Milliseconds(300), after));
  // Meanwhile calls still get the kept grid while they accept its age.
  EXPECT_EQ(Found(cache, whole, t0 + absl::Milliseconds(300), absl::Milliseconds(500)), 7u);
  cache.Put(whole, GridOfRevision(8), t0 + absl::Milliseconds(320));
  EXPECT_EQ(Found(cache, whole, t0 + absl::Milliseconds(330), absl::Milliseconds(500)), 8u);
  EXPECT_FALSE(cache.ClaimRefresh(whole, t0 + absl::Milliseconds(400), after));  // fresh again
  EXPECT_TRUE(cache.ClaimRefresh(whole, t0 + absl::Milliseconds(600), after));
  cache.EndRefresh(whole);  // the fetch failed: the next call may try again
  EXPECT_TRUE(cache.ClaimRefresh(whole, t0 + absl::Milliseconds(610), after));
}

}  // namespace
}  // namespace semnav::planning
