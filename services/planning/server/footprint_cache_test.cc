// FootprintCache: which calls share one prepared footprint.
#include "services/planning/server/footprint_cache.h"

#include "gtest/gtest.h"

namespace semnav::planning {
namespace {

using semnav::common::v1::GridMap;

// Counts the preparations; each footprint's radius says which call made it.
struct CountingPrepare {
  int calls = 0;
  PreparedFootprint operator()(double radius) {
    ++calls;
    PreparedFootprint footprint;
    footprint.robot_radius_m = radius;
    return footprint;
  }
};

TEST(FootprintCache, OneGridAndFootprintIsPreparedOnceWhileOthersArePreparedApart) {
  FootprintCache cache;
  CountingPrepare prepare;
  const auto grid = std::make_shared<const GridMap>();
  const auto newer = std::make_shared<const GridMap>();
  auto get = [&](const std::shared_ptr<const GridMap>& g, double radius, bool clearance) {
    return cache.Get(g, radius, clearance, [&] { return prepare(radius); });
  };
  const std::shared_ptr<const PreparedFootprint> first = get(grid, 0.3, true);
  EXPECT_EQ(get(grid, 0.3, true), first);  // the same object, not prepared again
  EXPECT_EQ(prepare.calls, 1);
  EXPECT_NE(get(grid, 0.2, true), first);   // another radius
  EXPECT_NE(get(grid, 0.3, false), first);  // without clearance
  EXPECT_NE(get(newer, 0.3, true), first);  // a newer grid
  EXPECT_EQ(prepare.calls, 4);
  EXPECT_EQ(get(grid, 0.3, true), first);
  EXPECT_EQ(prepare.calls, 4);
}

TEST(FootprintCache, AGridNobodyOwnsIsPreparedEachTime) {
  FootprintCache cache;
  CountingPrepare prepare;
  GridMap inline_grid;
  const std::shared_ptr<const GridMap> unowned(std::shared_ptr<const GridMap>(), &inline_grid);
  for (int call = 0; call < 2; ++call) {
    EXPECT_EQ(cache.Get(unowned, 0.3, true, [&] { return prepare(0.3); })->robot_radius_m, 0.3);
  }
  EXPECT_EQ(prepare.calls, 2);
}

TEST(FootprintCache, TheFootprintUsedLongestAgoGoesFirst) {
  FootprintCache cache(2);
  CountingPrepare prepare;
  std::vector<std::shared_ptr<const GridMap>> grids;
  for (int i = 0; i < 3; ++i) grids.push_back(std::make_shared<const GridMap>());
  auto get = [&](int i) { return cache.Get(grids[i], 0.3, true, [&] { return prepare(0.3); }); };
  get(0);
  get(1);
  get(0);  // grid 1 is now the one used longest ago
  get(2);  // evicts grid 1
  EXPECT_EQ(prepare.calls, 3);
  get(0);
  EXPECT_EQ(prepare.calls, 3);
  get(1);
  EXPECT_EQ(prepare.calls, 4);
}

TEST(FootprintCache, AFootprintGoesWithItsGrid) {
  FootprintCache cache;
  CountingPrepare prepare;
  auto grid = std::make_shared<const GridMap>();
  std::weak_ptr<const PreparedFootprint> footprint =
      cache.Get(grid, 0.3, true, [&] { return prepare(0.3); });
  EXPECT_FALSE(footprint.expired());  // kept while its grid lives
  grid.reset();                       // the live-grid cache lets the grid go
  const auto newer = std::make_shared<const GridMap>();
  cache.Get(newer, 0.3, true, [&] { return prepare(0.3); });
  EXPECT_TRUE(footprint.expired());  // dropped with it, not kept until evicted
  EXPECT_EQ(prepare.calls, 2);
}

}  // namespace
}  // namespace semnav::planning
