#include "services/planning/core/movingai.h"

#include <gtest/gtest.h>

#include <string>

#include "services/planning/core/astar.h"
#include "services/planning/core/jps.h"

namespace semnav::planning {
namespace {

const std::string kDataDir = std::string(SEMNAV_SHARED_DATA_DIR) + "/movingai-grid/";

TEST(MovingAi, LoadsArena2Header) {
  absl::StatusOr<PassabilityGrid> map = LoadMovingAiMap(kDataDir + "dao/arena2.map");
  ASSERT_TRUE(map.ok()) << map.status();
  EXPECT_EQ(map->width(), 281);
  EXPECT_EQ(map->height(), 209);
  absl::StatusOr<std::vector<MovingAiScenario>> rows =
      LoadMovingAiScenarios(kDataDir + "dao/arena2.map.scen");
  ASSERT_TRUE(rows.ok()) << rows.status();
  EXPECT_EQ(rows->size(), 910u);
}

TEST(MovingAi, MissingFileIsNotFound) {
  EXPECT_EQ(LoadMovingAiMap(kDataDir + "nope.map").status().code(), absl::StatusCode::kNotFound);
}

class MovingAiRows : public ::testing::TestWithParam<const char*> {};

// A deterministic sample of each map's rows (every 20th; every 100th on the
// long maze paths); the benchmark runs all 18,820 rows.
TEST_P(MovingAiRows, BothPlannersGiveTheOptimalLength) {
  const std::string base = kDataDir + GetParam();
  absl::StatusOr<PassabilityGrid> map = LoadMovingAiMap(base);
  ASSERT_TRUE(map.ok()) << map.status();
  absl::StatusOr<std::vector<MovingAiScenario>> rows = LoadMovingAiScenarios(base + ".scen");
  ASSERT_TRUE(rows.ok()) << rows.status();
  AStarPlanner astar;
  JpsPlanner jps;
  const size_t stride = base.find("maze") != std::string::npos ? 100 : 20;
  for (size_t i = 0; i < rows->size(); i += stride) {
    const MovingAiScenario& row = (*rows)[i];
    absl::StatusOr<GridPath> a = astar.Plan(*map, row.start, row.goal);
    absl::StatusOr<GridPath> j = jps.Plan(*map, row.start, row.goal);
    ASSERT_TRUE(a.ok()) << "row " << i << ": " << a.status();
    ASSERT_TRUE(j.ok()) << "row " << i << ": " << j.status();
    EXPECT_NEAR(a->length_cells, row.optimal_length, 1e-4) << "A* row " << i;
    EXPECT_NEAR(j->length_cells, row.optimal_length, 1e-4) << "JPS row " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Maps, MovingAiRows,
                         ::testing::Values("dao/arena2.map", "room/8room_000.map",
                                           "maze/maze512-1-0.map", "random/random512-10-0.map",
                                           "street/Berlin_0_512.map"));

}  // namespace
}  // namespace semnav::planning
