#include "services/planning/core/frontier_value.h"

#include <gtest/gtest.h>

#include <cmath>

#include "services/planning/core/exploration_goal.h"

namespace semnav::planning {
namespace {

// Rows drawn top = row 0: '.' explored free, '#' explored wall, '?' unexplored.
ExplorationGrid GridOf(const std::vector<std::string>& rows, double resolution) {
  ExplorationGrid grid;
  grid.resolution_m = resolution;
  const int w = static_cast<int>(rows[0].size());
  const int h = static_cast<int>(rows.size());
  grid.explored = CellGrid<uint8_t>(w, h, 0);
  grid.free = PassabilityGrid(w, h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      grid.explored.at(x, y) = rows[y][x] != '?';
      grid.free.at(x, y) = rows[y][x] == '.';
    }
  }
  return grid;
}

TEST(FrontierValue, GainCountsOnlyUnexploredSpaceReachableFromTheFrontier) {
  // Frontier column x=2 looks into 2 x 3 unknown cells; the 3 unknown cells behind the wall
  // column x=5 are not reachable through unknown space.
  const ExplorationGrid grid = GridOf({"...??#?", "...??#?", "...??#?"}, 0.5);
  ExplorationQuery query;
  query.robot = {0, 1};
  query.min_frontier_cells = 1;
  const FrontierSet set = CollectFrontiers(grid, query, {});
  ASSERT_EQ(set.frontiers.size(), 1u);
  FrontierValueConfig config;
  config.gain_radius_m = 100.0;
  const std::vector<FrontierValue> values =
      ValueFrontiers(set.frontiers, set.candidates, grid.explored, 0.5, {}, config);
  EXPECT_DOUBLE_EQ(values[0].gain_m2, 6 * 0.25);
  EXPECT_DOUBLE_EQ(values[0].evidence, 0.0);
  // Path distance 1 m (two cells east of the robot's column): U = G exp(-0.2 * 1).
  EXPECT_DOUBLE_EQ(set.candidates[0].path_distance_m, 1.0);
  EXPECT_NEAR(values[0].utility, 1.5 * std::exp(-0.2), 1e-12);
  // A radius of one cell from the centroid (2, 1) reaches only (3, 1).
  config.gain_radius_m = 0.5;
  EXPECT_DOUBLE_EQ(
      ValueFrontiers(set.frontiers, set.candidates, grid.explored, 0.5, {}, config)[0].gain_m2,
      0.25);
}

TEST(FrontierValue, EvidenceIsTheStrongestObjectSpreadByAGaussian) {
  const std::vector<Frontier> frontiers(1, Frontier{{{0, 0}}, 0.0, 0.0, {0, 0}});
  const std::vector<FrontierCandidate> candidates = {{{0.0, 0.0}, 1.0}};
  // Co-occurrence 0.8 at sigma (2 m); relevance 0.9 at 2 sigma; relation 0.3 on the spot.
  const std::vector<ScoredObject> objects = {
      {{2.0, 0.0}, 0.0, 0.0, 0.8}, {{0.0, 4.0}, 0.9, 0.0, 0.0}, {{0.0, 0.0}, 0.0, 0.3, 0.0}};
  const CellGrid<uint8_t> explored(1, 1, 1);
  const std::vector<FrontierValue> v =
      ValueFrontiers(frontiers, candidates, explored, 1.0, objects, {});
  EXPECT_NEAR(v[0].evidence, 0.8 * std::exp(-0.5), 1e-12);  // 0.485 > 0.9 e^-2 = 0.122, > 0.3
}

TEST(FrontierValue, RegionFirstThenTheBestFrontierInIt) {
  FrontierValueConfig config;  // semantic_gain 2, decay 0.2 / m, link 3 m, min gain 0.25 m2
  // A: alone, 1 m away, 2 m2. B and C: one region 6 m away; B 5 m2 at 6 m, C 10 m2 at 8 m.
  const std::vector<FrontierCandidate> candidates = {
      {{1.0, 0.0}, 1.0}, {{6.0, 0.0}, 6.0}, {{6.0, 2.0}, 8.0}};
  std::vector<FrontierValue> values(3);
  values[0] = {0.0, 2.0, 2.0 * std::exp(-0.2), 0};
  values[1] = {0.0, 5.0, 5.0 * std::exp(-1.2), 1};
  values[2] = {0.0, 10.0, 10.0 * std::exp(-1.6), 1};
  // Regions: A 2 e^-0.2 = 1.64; {B, C} 10 e^-1.2 = 3.01 -> {B, C}; inside, C 2.02 > B 1.51.
  EXPECT_EQ(SelectValuedFrontier(candidates, values, config), 2);
  // Evidence next to A (V = 1): 3 x 1.64 = 4.91 beats 3.01.
  values[0].evidence = 1.0;
  EXPECT_EQ(SelectValuedFrontier(candidates, values, config), 0);
  // A pocket below min_gain_m2 waits while anything else is worth a visit.
  values[0].gain_m2 = 0.1;
  EXPECT_EQ(SelectValuedFrontier(candidates, values, config), 2);
  // Nothing reachable: none.
  std::vector<FrontierCandidate> unreachable = candidates;
  for (FrontierCandidate& c : unreachable) c.path_distance_m = -1.0;
  EXPECT_FALSE(SelectValuedFrontier(unreachable, values, config).has_value());
}

// A corridor at 0.5 m cells: a one-cell unknown pocket at its west end, a 4 x 3 unknown room
// beyond its east end.
ExplorationGrid PocketAndRoomCorridor() {
  return GridOf(
      {
          "#########????",
          "?.......?????",
          "#########????",
      },
      0.5);
}

TEST(SelectExplorationGoal, SemanticFrontierOpensTheRoomNearestFrontierTakesThePocket) {
  // The robot at (4, 1). West: a one-cell pocket 2 cells away. East: a 4 x 3 unknown room
  // behind a frontier 3 cells away.
  const ExplorationGrid grid = PocketAndRoomCorridor();
  ExplorationQuery query;
  query.robot = {4, 1};
  query.min_frontier_cells = 1;
  ExplorationGoalConfig config;
  config.value.enabled = true;  // opt-in (frontier_value.h)
  absl::StatusOr<ExplorationChoice> nearest =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kNearestFrontier, config);
  ASSERT_TRUE(nearest.ok()) << nearest.status();
  EXPECT_EQ(nearest->goal, (Cell{1, 1}));
  absl::StatusOr<ExplorationChoice> semantic =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, config);
  ASSERT_TRUE(semantic.ok()) << semantic.status();
  EXPECT_EQ(semantic->goal, (Cell{7, 1}));
  // Both frontiers are 1.5 m away. East: 13 unknown cells within 3 m = 3.25 m2, U = 3.25 e^-0.3.
  // West: 1 cell = 0.25 m2. An object co-occurring with the target (1.0) just beyond the west
  // pocket, 0.5 m from its frontier, with sigma 0.5 m: V = e^-0.5 = 0.61; at gain 40,
  // U_west = (1 + 40 x 0.61) 0.25 e^-0.3 = 4.7 e^-0.3 > 3.25 e^-0.3 (east's V = e^-24.5 ~ 0).
  query.objects = {{grid.CentreOf(Cell{0, 1}), 0.0, 0.0, 1.0}};
  config.value.evidence_sigma_m = 0.5;
  config.value.semantic_gain = 40.0;
  semantic = SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, config);
  ASSERT_TRUE(semantic.ok()) << semantic.status();
  EXPECT_EQ(semantic->goal, (Cell{1, 1}));
}

// A ground robot at (4, 1) in PocketAndRoomCorridor, every frontier cell counted.
ExplorationQuery GroundRobotInTheCorridor() {
  ExplorationQuery query;
  query.robot = {4, 1};
  query.min_frontier_cells = 1;
  query.platform = ExplorationPlatform::kGround;
  return query;
}

ExplorationGoalConfig DiscountOnTheGround() {
  ExplorationGoalConfig config;
  config.discount.ground = true;  // opt-in
  return config;
}

TEST(SelectExplorationGoal, AGoalToKeepIsAnsweredWhileItsFrontierIsOpen) {
  // The robot at (4, 1): the west pocket (1, 1) is the nearest frontier; the east room's frontier
  // cell is (7, 1), centre (3.75, 0.75).
  const ExplorationGrid grid = PocketAndRoomCorridor();
  ExplorationQuery query = GroundRobotInTheCorridor();
  const ExplorationGoalConfig config = DiscountOnTheGround();
  for (const ExplorationStrategy strategy :
       {ExplorationStrategy::kNearestFrontier, ExplorationStrategy::kSemanticFrontier}) {
    // Kept: 0.3 m from the east frontier cell, within the 1 m radius.
    query.keep_goal = Point2{4.05, 0.75};
    absl::StatusOr<ExplorationChoice> choice = SelectExplorationGoal(grid, query, strategy, config);
    ASSERT_TRUE(choice.ok()) << choice.status();
    EXPECT_EQ(choice->goal, (Cell{7, 1}));
    // 0.6 m from it with a 0.5 m radius: that frontier is gone from there; the best answers.
    query.keep_goal = Point2{4.35, 0.75};
    query.keep_radius_m = 0.5;
    choice = SelectExplorationGoal(grid, query, strategy, config);
    ASSERT_TRUE(choice.ok()) << choice.status();
    EXPECT_EQ(choice->goal, (Cell{1, 1}));
    // An excluded frontier is not kept either.
    query.keep_goal = Point2{3.75, 0.75};
    query.keep_radius_m = 1.0;
    query.excluded = [](Point2 p) { return p.x > 3.0; };
    choice = SelectExplorationGoal(grid, query, strategy, config);
    ASSERT_TRUE(choice.ok()) << choice.status();
    EXPECT_EQ(choice->goal, (Cell{1, 1}));
    query.excluded = nullptr;
  }
}

TEST(SelectExplorationGoal, SemanticDiscountWithoutEvidenceIsTheNearestFrontierSearch) {
  // The same corridor: the west pocket (2 cells) is nearer than the east room (3 cells).
  const ExplorationGrid grid = PocketAndRoomCorridor();
  ExplorationQuery query = GroundRobotInTheCorridor();
  const ExplorationGoalConfig config = DiscountOnTheGround();
  absl::StatusOr<ExplorationChoice> semantic =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, config);
  ASSERT_TRUE(semantic.ok()) << semantic.status();
  EXPECT_EQ(semantic->goal, (Cell{1, 1}));  // NEAREST_FRONTIER's goal
  // An object co-occurring with the target beside the east room (evidence 1): U_east =
  // 3 / (1.5 + 1) = 1.2 beats U_west = 1 / (1 + 1) = 0.5; the goal is the room's nearest cell.
  query.objects = {{grid.CentreOf(Cell{9, 1}), 0.0, 0.0, 1.0}};
  semantic = SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, config);
  ASSERT_TRUE(semantic.ok()) << semantic.status();
  EXPECT_EQ(semantic->goal, (Cell{7, 1}));
}

TEST(SelectExplorationGoal, TheDiscountAppliesOnlyToTheConfiguredPlatforms) {
  // 1 m cells, row 0 first. From (0, 0) the upper-left cluster is 3 m away and the right one
  // (column 5 and row 3's east end) 5 m; an object co-occurring with the target at (7, 0).
  const ExplorationGrid grid =
      GridOf({"......??", "......??", "..##..??", "........", "???....."}, 1.0);
  ExplorationQuery query;
  query.robot = {0, 0};
  query.min_frontier_cells = 1;
  query.objects = {{grid.CentreOf(Cell{7, 0}), 0.0, 0.0, 1.0}};
  const FrontierSet set = CollectFrontiers(grid, query, FrontierScoreConfig{});
  int best_total = -1;
  for (size_t i = 0; i < set.scores.size(); ++i) {
    if (best_total < 0 || set.scores[i].total > set.scores[best_total].total) {
      best_total = static_cast<int>(i);
    }
  }
  ASSERT_GE(best_total, 0);
  ASSERT_NE(set.frontiers[best_total].anchor, (Cell{5, 0}));
  // By default no platform takes the discount: the seed total's anchor.
  for (ExplorationPlatform platform : {ExplorationPlatform::kGround, ExplorationPlatform::kAerial,
                                       ExplorationPlatform::kUnspecified}) {
    query.platform = platform;
    absl::StatusOr<ExplorationChoice> semantic =
        SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, {});
    ASSERT_TRUE(semantic.ok()) << semantic.status();
    EXPECT_EQ(semantic->goal, set.frontiers[best_total].anchor);
  }
  // Ground robots opted in: U_right = (1 + 2 S) / (5 + 1) > U_left = 1 / (3 + 1) for S > 0.25;
  // the goal is the right cluster's nearest cell (5, 0). Aerial requests keep the seed total.
  ExplorationGoalConfig config;
  config.discount.ground = true;
  query.platform = ExplorationPlatform::kGround;
  absl::StatusOr<ExplorationChoice> ground =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, config);
  ASSERT_TRUE(ground.ok()) << ground.status();
  EXPECT_EQ(ground->goal, (Cell{5, 0}));
  query.platform = ExplorationPlatform::kAerial;
  absl::StatusOr<ExplorationChoice> aerial =
      SelectExplorationGoal(grid, query, ExplorationStrategy::kSemanticFrontier, config);
  ASSERT_TRUE(aerial.ok()) << aerial.status();
  EXPECT_EQ(aerial->goal, set.frontiers[best_total].anchor);
}

TEST(SelectExplorationGoal, NothingReachableIsNotFoundWithItsReason) {
  const ExplorationGrid grid = GridOf({"...", "...", "..."}, 0.5);
  ExplorationQuery query;
  query.robot = {1, 1};
  for (ExplorationStrategy s :
       {ExplorationStrategy::kNearestFrontier, ExplorationStrategy::kSemanticFrontier}) {
    absl::StatusOr<ExplorationChoice> choice = SelectExplorationGoal(grid, query, s, {});
    EXPECT_EQ(choice.status().code(), absl::StatusCode::kNotFound);
  }
}

}  // namespace
}  // namespace semnav::planning
