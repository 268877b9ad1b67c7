#include "services/planning/core/jump_astar_cache.h"

#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "services/planning/core/plan_failure.h"
#include "services/planning/core/random_layered_map.h"

namespace semnav::planning {
namespace {

// Holds the jobs the cache hands off, so the test decides when they run.
struct QueuedJobs {
  std::vector<std::function<void()>> jobs;
  JumpAStarCache::RunLater Sink() {
    return [this](std::function<void()> job) { jobs.push_back(std::move(job)); };
  }
  void RunAll() {
    for (auto& job : jobs) job();
    jobs.clear();
  }
};

constexpr size_t kPlenty = size_t{1} << 30;

RandomLayeredMap SmallMap(uint32_t seed) {
  return MakeRandomLayeredMap({.size_m = 12.0, .obstacle_count = 25, .seed = seed});
}

TEST(JumpAStarCache, LandmarksAreBuiltOffTheQueryFromTheSecondQueryOn) {
  const RandomLayeredMap map = SmallMap(3);
  QueuedJobs queue;
  JumpAStarCache cache(kPlenty, queue.Sink());
  JumpAStarPlanner cold;
  const JumpAStarOptions options;
  absl::StatusOr<MultiModalPath> reference = cold.Plan(map.grid, map.start, map.goal, options);
  ASSERT_TRUE(reference.ok()) << reference.status();

  absl::StatusOr<MultiModalPath> first = cache.Plan(map.grid, map.start, map.goal, options);
  ASSERT_TRUE(first.ok());
  EXPECT_TRUE(queue.jobs.empty());  // a one-off grid pays for no landmarks
  EXPECT_EQ(first->expansions, reference->expansions);

  absl::StatusOr<MultiModalPath> second = cache.Plan(map.grid, map.start, map.goal, options);
  ASSERT_TRUE(second.ok());
  ASSERT_EQ(queue.jobs.size(), 1u);  // handed off, not run inside the query
  EXPECT_EQ(second->expansions, reference->expansions);
  queue.RunAll();

  absl::StatusOr<MultiModalPath> warm = cache.Plan(map.grid, map.start, map.goal, options);
  ASSERT_TRUE(warm.ok());
  EXPECT_TRUE(queue.jobs.empty());  // built once
  EXPECT_LT(warm->expansions, reference->expansions);
  EXPECT_NEAR(warm->cost, reference->cost, 1e-9);
  EXPECT_EQ(warm->waypoints, reference->waypoints);
  EXPECT_DOUBLE_EQ(warm->energy_j, reference->energy_j);
}

TEST(JumpAStarCache, ChangedGridOrCostsAreNewEntries) {
  RandomLayeredMap map = SmallMap(3);
  QueuedJobs queue;
  JumpAStarCache cache(kPlenty, queue.Sink());
  const JumpAStarOptions options;
  for (int i = 0; i < 2; ++i) ASSERT_TRUE(cache.Plan(map.grid, map.start, map.goal, options).ok());
  queue.RunAll();
  // One cell changed: the cached landmarks no longer hold, so the query must
  // match a cold planner on the new grid, and the new grid starts over.
  map.grid.at(map.start.x + 3, map.start.y + 3) = 90;
  JumpAStarPlanner cold;
  absl::StatusOr<MultiModalPath> expected = cold.Plan(map.grid, map.start, map.goal, options);
  absl::StatusOr<MultiModalPath> changed = cache.Plan(map.grid, map.start, map.goal, options);
  ASSERT_TRUE(expected.ok() && changed.ok());
  EXPECT_EQ(changed->expansions, expected->expansions);
  EXPECT_EQ(changed->waypoints, expected->waypoints);
  EXPECT_TRUE(queue.jobs.empty());
  // Other weights: the landmarks of beta 1 are not reused.
  JumpAStarOptions beta5 = options;
  beta5.beta = 5.0;
  expected = cold.Plan(map.grid, map.start, map.goal, beta5);
  changed = cache.Plan(map.grid, map.start, map.goal, beta5);
  ASSERT_TRUE(expected.ok() && changed.ok());
  EXPECT_EQ(changed->expansions, expected->expansions);
}

TEST(JumpAStarCache, LeastRecentlyUsedMapIsDroppedOverBudget) {
  QueuedJobs queue;
  JumpAStarCache cache(1, queue.Sink());  // 1 byte: only the newest map stays
  const JumpAStarOptions options;
  const RandomLayeredMap a = SmallMap(1);
  const RandomLayeredMap b = SmallMap(2);
  ASSERT_TRUE(cache.Plan(a.grid, a.start, a.goal, options).ok());
  ASSERT_TRUE(cache.Plan(b.grid, b.start, b.goal, options).ok());  // drops a
  ASSERT_TRUE(cache.Plan(a.grid, a.start, a.goal, options).ok());  // a is new again
  EXPECT_TRUE(queue.jobs.empty());
  ASSERT_TRUE(cache.Plan(a.grid, a.start, a.goal, options).ok());
  EXPECT_EQ(queue.jobs.size(), 1u);
}

// A budget that holds two maps' tables but not landmarks on top: when b's
// landmarks arrive, a (least recently used) goes, and b keeps them.
TEST(JumpAStarCache, LandmarksArrivingOverBudgetDropTheOldestMap) {
  const RandomLayeredMap a = SmallMap(1);
  const RandomLayeredMap b = SmallMap(2);
  const size_t two_tables = RegionTables(a.grid).bytes() + RegionTables(b.grid).bytes();
  QueuedJobs queue;
  JumpAStarCache cache(two_tables, queue.Sink());
  const JumpAStarOptions options;
  JumpAStarPlanner cold;
  const int a_cold = cold.Plan(a.grid, a.start, a.goal, options)->expansions;
  const int b_cold = cold.Plan(b.grid, b.start, b.goal, options)->expansions;
  ASSERT_TRUE(cache.Plan(a.grid, a.start, a.goal, options).ok());
  ASSERT_TRUE(cache.Plan(b.grid, b.start, b.goal, options).ok());
  ASSERT_TRUE(cache.Plan(b.grid, b.start, b.goal, options).ok());  // hands off b's landmarks
  ASSERT_EQ(queue.jobs.size(), 1u);
  queue.RunAll();
  EXPECT_LT(cache.Plan(b.grid, b.start, b.goal, options)->expansions, b_cold);  // warm
  // a was dropped: its next query is a first query again (no landmark job).
  EXPECT_EQ(cache.Plan(a.grid, a.start, a.goal, options)->expansions, a_cold);
  EXPECT_TRUE(queue.jobs.empty());
}

// Structure splits the grid into two rooms: from the third query on the
// landmark bound between them is infinite, which must still say NO_PATH.
TEST(JumpAStarCache, NoPathAlsoWithTheLandmarkBound) {
  LayeredGrid grid(7, 3, 0);
  for (int y = 0; y < grid.height(); ++y) grid.at(3, y) = kStructureValue;
  QueuedJobs queue;
  JumpAStarCache cache(kPlenty, queue.Sink());
  const JumpAStarOptions options;
  for (int query = 0; query < 3; ++query) {
    EXPECT_EQ(PlanFailureOf(cache.Plan(grid, {0, 0}, {6, 2}, options).status()),
              PlanFailure::kNoPath)
        << "query " << query;
    queue.RunAll();
  }
  EXPECT_EQ(PlanFailureOf(cache.Plan(grid, {3, 1}, {6, 2}, options).status()),
            PlanFailure::kStartOccupied);
  EXPECT_TRUE(cache.Plan(grid, {4, 0}, {6, 2}, options).ok());
}

}  // namespace
}  // namespace semnav::planning
