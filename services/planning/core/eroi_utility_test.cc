#include "services/planning/core/eroi_utility.h"

#include <gtest/gtest.h>

#include <cmath>

#include "services/planning/core/exploration_goal.h"

namespace semnav::planning {
namespace {

ExplorationLayers AllUnknown(int w, int h) {
  return {CellGrid<uint8_t>(w, h, 0), PassabilityGrid(w, h, 0)};
}

void MarkFree(ExplorationLayers* l, int x, int y) {
  l->explored.at(x, y) = 1;
  l->free.at(x, y) = 1;
}

TEST(EroiUtility, ViewpointGainCountsUnknownCellsUntilAnObstacle) {
  ExplorationLayers layers = AllUnknown(21, 21);
  MarkFree(&layers, 10, 10);
  EroiConfig config;
  config.rays = 4;  // east, north, west, south
  config.ray_range_cells = 5;
  EXPECT_EQ(ViewpointGain(layers, {10, 10}, config), 20);  // 4 rays x 5 unknown cells
  layers.explored.at(12, 10) = 1;                          // an explored obstacle 2 cells east
  EXPECT_EQ(ViewpointGain(layers, {10, 10}, config), 16);  // east ray: 1 cell, then stops
}

// 60 x 20 cells, three 20-cell EROIs; everything explored and free except
// a 5 x 10 block at x 15-19, y 0-9 (EROI 0, near the robot) and the strip
// x 55-59 (EROI 2, far away). The robot at (2, 15) passes below the block.
ExplorationLayers TwoUnknownStrips() {
  ExplorationLayers layers = AllUnknown(60, 20);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 55; ++x) {
      if (x < 15 || x > 19 || y >= 10) MarkFree(&layers, x, y);
    }
  }
  return layers;
}

EroiConfig SmallConfig() {
  EroiConfig config;
  config.eroi_size_cells = 20;
  config.viewpoint_radius_cells = 5;
  config.ray_range_cells = 30;
  config.lambda = 0.05;  // the strips are drawn for a steep path cost: 1 per 20 cells
  return config;
}

// The default path cost (0.01 per cell, 0.2 per m at 5 cm) halves the utility every 70 cells:
// with no clue, the far strip's larger unknown area, some 35 cells farther, outweighs the near
// block. At 0.05 per cell (the old default, SmallConfig) the near block wins, and the UAV went
// from one nearest pocket of unknown to the next (docs/performance/mission.md, "A gentler path
// cost").
TEST(EroiUtility, TheDefaultPathCostLetsALargerUnknownAreaAFewMetresOnWin) {
  const ExplorationLayers layers = TwoUnknownStrips();
  EroiConfig config = SmallConfig();
  config.lambda = EroiConfig{}.lambda;
  ASSERT_DOUBLE_EQ(config.lambda, 0.01);
  std::optional<EroiChoice> gentle = SelectEroiGoal(layers, {2, 15}, {}, config);
  std::optional<EroiChoice> steep = SelectEroiGoal(layers, {2, 15}, {}, SmallConfig());
  ASSERT_TRUE(gentle.has_value());
  ASSERT_TRUE(steep.has_value());
  EXPECT_EQ(gentle->eroi, 2);
  EXPECT_EQ(steep->eroi, 0);
  EXPECT_GT(gentle->gain, steep->gain);
  EXPECT_GT(gentle->path_cells, steep->path_cells + 20.0);
  EXPECT_NEAR(gentle->utility, gentle->gain / 3.0 * std::exp(-0.01 * gentle->path_cells), 1e-12);
}

TEST(EroiUtility, HighSemanticValueIgnoresPathCost) {
  const ExplorationLayers layers = TwoUnknownStrips();
  EroiConfig config = SmallConfig();
  ASSERT_EQ(EroiCount(60, 20, config), 3);
  // s = 1.0 for the far EROI exceeds tau = 0.8: greedy, no e^(-lambda L).
  std::optional<EroiChoice> choice = SelectEroiGoal(layers, {2, 15}, {0.2, 0.0, 1.0}, config);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->eroi, 2);
  EXPECT_GT(choice->path_cells, 40.0);
  EXPECT_DOUBLE_EQ(choice->utility, choice->gain * 1.0);
  EXPECT_EQ(choice->route.front(), (Cell{2, 15}));
  EXPECT_EQ(choice->route.back(), choice->viewpoint);
}

TEST(EroiUtility, PathCostFavoursTheNearerEroiBelowTheThreshold) {
  const ExplorationLayers layers = TwoUnknownStrips();
  EroiConfig config = SmallConfig();
  config.k = 1.0;  // tau = max s: every node pays the path cost
  std::optional<EroiChoice> choice = SelectEroiGoal(layers, {2, 15}, {0.3, 0.0, 0.3}, config);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->eroi, 0);
  EXPECT_NEAR(choice->utility, choice->gain * 0.3 * std::exp(-config.lambda * choice->path_cells),
              1e-12);
}

// Regression (issue 15): without a clue (uniform values, 1/3 each) every s equals max s > tau,
// and eq. 24 read literally dropped the path cost for every node: the far strip's larger gain
// won and the UAV zig-zagged across the area. A clue is a value above the floor; without one
// every node pays the path cost, so the nearer EROI wins.
TEST(EroiUtility, WithoutAClueEveryViewpointPaysThePathCost) {
  const ExplorationLayers layers = TwoUnknownStrips();
  for (const std::vector<double>& values :
       {std::vector<double>{}, std::vector<double>{1.0 / 3, 1.0 / 3, 1.0 / 3}}) {
    std::optional<EroiChoice> uniform = SelectEroiGoal(layers, {2, 15}, values, SmallConfig());
    ASSERT_TRUE(uniform.has_value());
    EXPECT_EQ(uniform->eroi, 0) << values.size();
    EXPECT_NEAR(uniform->utility,
                uniform->gain / 3.0 * std::exp(-SmallConfig().lambda * uniform->path_cells), 1e-12);
  }
  // A clue in the far EROI (above the floor and above tau): greedy again.
  std::optional<EroiChoice> clue =
      SelectEroiGoal(layers, {2, 15}, {1.0 / 3, 1.0 / 3, 0.5}, SmallConfig());
  ASSERT_TRUE(clue.has_value());
  EXPECT_EQ(clue->eroi, 2);
  EXPECT_DOUBLE_EQ(clue->utility, clue->gain * 0.5);
}

// Regression (issue 15): between two clues eq. 24 read literally chose by I s alone, and the UAV
// flew 20 m legs back and forth along a road whose codes the model named. Both EROIs here are
// clues (0.9 and 1.0 > tau 0.8, above the floor 0); the far strip's gain (100 cells) and value beat
// the near block's (50 cells), but it lies 40+ cells farther: it pays e^(-lambda (L - L_near)).
TEST(EroiUtility, TheFartherOfTwoCluesPaysThePathBeyondTheNearer) {
  const ExplorationLayers layers = TwoUnknownStrips();
  EroiConfig config = SmallConfig();
  std::optional<EroiChoice> choice = SelectEroiGoal(layers, {2, 15}, {0.9, 0.0, 1.0}, config);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->eroi, 0);
  EXPECT_LT(choice->path_cells, 20.0);
  EXPECT_LE(choice->utility, choice->gain * 0.9);  // the nearest clue viewpoint pays nothing
  config.clues_pay_extra_path = false;             // the seed's reading
  choice = SelectEroiGoal(layers, {2, 15}, {0.9, 0.0, 1.0}, config);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->eroi, 2);
  EXPECT_DOUBLE_EQ(choice->utility, choice->gain * 1.0);
}

// Regression (issue 15, the UAV's closed loop): a robot standing in explored space wider than
// the connect radius had no straight roadmap edge to any viewpoint, so no goal at all; the
// gateway then took blind 3 m steps east. 100 x 20 cells, all explored and free but the strip
// x >= 90; the robot at (2, 10) is 80+ cells (> 60) from EROI 4's viewpoints.
TEST(EroiUtility, ReachesViewpointsBeyondTheConnectRadiusThroughExploredSpace) {
  ExplorationLayers layers = AllUnknown(100, 20);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 90; ++x) MarkFree(&layers, x, y);
  }
  EroiConfig config = SmallConfig();
  ASSERT_EQ(config.connect_radius_cells, 60.0);
  std::optional<EroiChoice> choice = SelectEroiGoal(layers, {2, 10}, {}, config);
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->eroi, 4);  // the only active EROI (x 80-99)
  // Viewpoints at radius 5 round (90, 10) on explored cells: x 85 or 86.5 -> path 83-85 cells.
  EXPECT_GE(choice->path_cells, 83.0);
  EXPECT_LE(choice->path_cells, 86.0);
  EXPECT_EQ(choice->route.front(), (Cell{2, 10}));
  EXPECT_EQ(choice->route.back(), choice->viewpoint);
}

// Regression (issue 15): a UAV's map reaches past the search area's edge; a viewpoint there took
// it out of the world. 100 x 20 cells of 5 cm, explored and free except a 5 x 5 pocket at the
// origin and the band x 84-91, y 0-15; the area ends at x = 4.6 m, so cells x >= 92 lie outside.
// EROI 4's (centre (90, 10)) only explored viewpoints, x 94-95, are outside.
TEST(EroiUtility, ViewpointsStayInsideTheSearchArea) {
  ExplorationGrid grid;
  grid.resolution_m = 0.05;
  grid.explored = CellGrid<uint8_t>(100, 20, 0);
  grid.free = PassabilityGrid(100, 20, 0);
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 100; ++x) {
      if ((x < 5 && y < 5) || (x >= 84 && x <= 91 && y <= 15)) continue;
      grid.explored.at(x, y) = 1;
      grid.free.at(x, y) = 1;
    }
  }
  ExplorationQuery query;
  query.robot = {50, 10};
  ExplorationGoalConfig config;
  config.eroi = SmallConfig();
  absl::StatusOr<ExplorationChoice> unbounded =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kEroiUtility, config);
  ASSERT_TRUE(unbounded.ok()) << unbounded.status();
  EXPECT_GE(unbounded->goal.x, 92);  // without an area the band's bigger gain wins
  query.outside_area = [](Point2 p) { return p.x > 4.6; };
  absl::StatusOr<ExplorationChoice> bounded =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kEroiUtility, config);
  ASSERT_TRUE(bounded.ok()) << bounded.status();
  EXPECT_LT(bounded->goal.x, 20);  // EROI 0, round the pocket
  EXPECT_LT(bounded->goal.y, 20);
}

// Regression (issue 15): a clue EROI's last few unknown cells (depth noise) outweighed whole
// unexplored areas, its value being ~100x the prior, and the UAV flew back and forth between clue
// EROIs. Viewpoints revealing fewer than min_gain_cells are dropped.
TEST(EroiUtility, ViewpointsBelowTheMinimumGainAreDropped) {
  ExplorationLayers layers = TwoUnknownStrips();
  // The far strip shrinks to 3 unknown cells; the near block stays (50 cells).
  for (int y = 0; y < 20; ++y) {
    for (int x = 55; x < 60; ++x) {
      if (!(x == 57 && y >= 9 && y <= 11)) MarkFree(&layers, x, y);
    }
  }
  EroiConfig config = SmallConfig();
  config.ray_range_cells = 10;  // the far EROI's viewpoints see the speck only, not the block
  const std::vector<double> clue_far = {0.01, 0.01, 0.9};
  std::optional<EroiChoice> speck = SelectEroiGoal(layers, {2, 15}, clue_far, config);
  ASSERT_TRUE(speck.has_value());
  EXPECT_EQ(speck->eroi, 2);  // 3 cells x 0.9 beat 50 cells x 0.01
  EXPECT_LE(speck->gain, 3.0);
  config.min_gain_cells = 10;
  std::optional<EroiChoice> block = SelectEroiGoal(layers, {2, 15}, clue_far, config);
  ASSERT_TRUE(block.has_value());
  EXPECT_EQ(block->eroi, 0);
  EXPECT_GE(block->gain, 10.0);
}

// Regression (issue 15, outdoor_road_vehicles start 4): the viewpoint the UAV stood on kept its
// gain (what is left unknown there is out of the camera's view) and, at path length 0, won again
// and again: 30 exploration goals at one spot in 7 s. The caller's spent goals hold no viewpoint.
TEST(EroiUtility, ExcludedViewpointsAreNotChosen) {
  const ExplorationLayers layers = TwoUnknownStrips();
  const EroiConfig config = SmallConfig();
  std::optional<EroiChoice> first = SelectEroiGoal(layers, {2, 15}, {}, config);
  ASSERT_TRUE(first.has_value());
  const Cell spent = first->viewpoint;
  const auto near_spent = [&](Cell c) { return std::hypot(c.x - spent.x, c.y - spent.y) <= 1.0; };
  std::optional<EroiChoice> next = SelectEroiGoal(layers, {2, 15}, {}, config, near_spent);
  ASSERT_TRUE(next.has_value());
  EXPECT_GT(std::hypot(next->viewpoint.x - spent.x, next->viewpoint.y - spent.y), 1.0);
}

}  // namespace
}  // namespace semnav::planning
