#include "services/planning/core/landmark_heuristic.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::planning {
namespace {

// A free 10 x 1 corridor: the corner landmarks are its two ends, so the
// bound to the goal at x = 9 is exactly the rolling cost of the gap.
TEST(LandmarkHeuristic, ExactAlongACorridor) {
  const LayeredGrid grid(10, 1, 0);
  LandmarkHeuristic h;
  const StepCosts costs{1.5, 2.0};
  h.Reset(grid, costs);
  ASSERT_TRUE(h.Matches(costs));
  EXPECT_FALSE(h.Matches(StepCosts{1.5, 2.5}));
  h.SetGoal(9);
  EXPECT_EQ(h.Bound(0), 0.0);  // no landmark computed yet
  ASSERT_TRUE(h.AddLandmark(grid));  // the left end: already exact here
  h.SetGoal(9);
  EXPECT_NEAR(h.Bound(0), 1.5 * 9, 1e-7);
  while (h.AddLandmark(grid)) {
  }
  h.SetGoal(9);
  for (int x = 0; x < 10; ++x) EXPECT_NEAR(h.Bound(x), 1.5 * (9 - x), 1e-7) << x;
  // Never above the true cost, even by rounding.
  EXPECT_LE(h.Bound(0), 1.5 * 9);
}

// An obstacle cell in the corridor makes the two moves touching it fly.
TEST(LandmarkHeuristic, CountsTheUnavoidableFlight) {
  LayeredGrid grid(10, 1, 0);
  grid.at(5, 0) = 40;
  LandmarkHeuristic h;
  h.Reset(grid, StepCosts{1.0, 3.0});
  while (h.AddLandmark(grid)) {
  }
  h.SetGoal(9);
  EXPECT_NEAR(h.Bound(0), 7 * 1.0 + 2 * 3.0, 1e-7);
  EXPECT_NEAR(h.Bound(6), 3 * 1.0, 1e-7);
}

// Cells cut off from the goal by structure get an infinite bound.
TEST(LandmarkHeuristic, DisconnectedCellsAreUnbounded) {
  LayeredGrid grid(5, 1, 0);
  grid.at(2, 0) = kStructureValue;
  LandmarkHeuristic h;
  h.Reset(grid, StepCosts{1.0, 2.0});
  while (h.AddLandmark(grid)) {
  }
  h.SetGoal(4);
  EXPECT_TRUE(std::isinf(h.Bound(0)));
  EXPECT_NEAR(h.Bound(3), 1.0, 1e-7);
}

}  // namespace
}  // namespace semnav::planning
