#include "services/planning/core/frontier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "services/planning/core/coverage_goal.h"
#include "services/planning/core/distance_field.h"
#include "services/planning/core/test_grids.h"

namespace semnav::planning {
namespace {

// Explored cells drawn as rows: '.' explored free, '@' explored obstacle,
// '?' unexplored.
struct Drawn {
  CellGrid<uint8_t> explored;
  PassabilityGrid free;
};
Drawn Draw(const std::vector<std::string>& rows) {
  Drawn d{CellGrid<uint8_t>(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 0),
          PassabilityGrid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()), 0)};
  for (int y = 0; y < d.free.height(); ++y) {
    for (int x = 0; x < d.free.width(); ++x) {
      d.explored.at(x, y) = rows[y][x] != '?';
      d.free.at(x, y) = rows[y][x] == '.';
    }
  }
  return d;
}

TEST(Frontier, ClustersCentroidsAndSizes) {
  const Drawn d = Draw({
      "......??",
      "......??",
      "@@@@@@@@",
      "........",
      "???.....",
  });
  const std::vector<Frontier> frontiers = ExtractFrontiers(d.explored, d.free, 1);
  ASSERT_EQ(frontiers.size(), 2u);
  // Top-right: cells (5,0), (5,1). Bottom-left: (0,3), (1,3), (2,3) above
  // unexplored cells, and (3,4) beside one.
  std::vector<size_t> sizes = {frontiers[0].cells.size(), frontiers[1].cells.size()};
  EXPECT_EQ(sizes[0], 2u);
  EXPECT_EQ(sizes[1], 4u);
  EXPECT_DOUBLE_EQ(frontiers[0].centroid_x, 5.0);
  EXPECT_DOUBLE_EQ(frontiers[0].centroid_y, 0.5);
  EXPECT_DOUBLE_EQ(frontiers[1].centroid_x, 1.5);
  EXPECT_DOUBLE_EQ(frontiers[1].centroid_y, 3.25);
  // min_cells drops the small cluster.
  EXPECT_EQ(ExtractFrontiers(d.explored, d.free, 3).size(), 1u);
}

TEST(Frontier, NearestIsByPathNotStraightLine) {
  // The top-right frontier is 3 cells away in a straight line but behind a
  // wall; the bottom one is reachable.
  const Drawn d = Draw({
      "....@.??",
      "....@.??",
      "....@...",
      "........",
      "??......",
  });
  const std::vector<Frontier> frontiers = ExtractFrontiers(d.explored, d.free, 1);
  std::optional<NearestFrontier> nearest =
      SelectNearestFrontier(frontiers, d.free, OctileDistanceField(d.free, {3, 0}));
  ASSERT_TRUE(nearest.has_value());
  // (3,0) -> (1,3): dx 2, dy 3 -> 1 + 2 sqrt2 = 3.83; the nearest cell of
  // the other frontier, (6,2), is 5 + sqrt2 away round the wall's end.
  EXPECT_EQ(nearest->cell, (Cell{1, 3}));
  EXPECT_NEAR(nearest->distance_cells, 1 + 2 * std::sqrt(2.0), 1e-12);
}

TEST(CoverageGoal, BoundaryPointAheadOfTheRobot) {
  const PassabilityGrid open(20, 20, 1);
  CoverageGoalConfig config;
  // Heading +x from (5,10): sqrt2 * 20 / 2 = 14.1 cells ahead, clamped to x = 19.
  EXPECT_EQ(CoverageMaxGoal(open, {5, 10}, 0.0, config), (Cell{19, 10}));
  // Heading 45 degrees: (5 + 10, 10 + 10) clamped to the corner (15, 19).
  EXPECT_EQ(CoverageMaxGoal(open, {5, 10}, std::numbers::pi / 4, config), (Cell{15, 19}));
}

TEST(CoverageGoal, TurnsWhenTheWayAheadIsBlocked) {
  PassabilityGrid grid(20, 20, 1);
  for (int y = 0; y < 20; ++y) grid.at(6, y) = 0;  // a wall right in front
  CoverageGoalConfig config;
  const std::optional<Cell> goal = CoverageMaxGoal(grid, {5, 10}, 0.0, config);
  ASSERT_TRUE(goal.has_value());
  EXPECT_LE(goal->x, 5);  // it turned away from the wall
  EXPECT_TRUE(CoverageGoalExpired(26, false, config));
  EXPECT_FALSE(CoverageGoalExpired(25, false, config));
  EXPECT_TRUE(CoverageGoalExpired(0, true, config));
}

}  // namespace
}  // namespace semnav::planning
