#include "services/planning/core/landmark_heuristic.h"

#include <gtest/gtest.h>

#include <cmath>

namespace semnav::planning {
namespace {

// A free 10 x 1 corridor: the corner landmarks are its two ends, so the
// bound to the goal at x = 9 is exactly the rolling cost of the gap.
TEST(LandmarkHeuristic, ExactAlongACorridor) {
  const LayeredGrid grid(10, 1, 0);
  const StepCosts costs{1.5, 2.0};
  const LandmarkHeuristic h(grid, costs);
  EXPECT_EQ(h.costs(), costs);
  const LandmarkHeuristic::ToGoal bound = h.Towards(9);
  for (int x = 0; x < 10; ++x) EXPECT_NEAR(bound(x), 1.5 * (9 - x), 1e-7) << x;
  // Never above the true cost, even by rounding.
  EXPECT_LE(bound(0), 1.5 * 9);
  // Symmetric: towards the other end.
  EXPECT_NEAR(h.Towards(0)(9), 1.5 * 9, 1e-7);
}

// An obstacle cell in the corridor makes the two moves touching it fly.
TEST(LandmarkHeuristic, CountsTheUnavoidableFlight) {
  LayeredGrid grid(10, 1, 0);
  grid.at(5, 0) = 40;
  const LandmarkHeuristic h(grid, StepCosts{1.0, 3.0});
  const LandmarkHeuristic::ToGoal bound = h.Towards(9);
  EXPECT_NEAR(bound(0), 7 * 1.0 + 2 * 3.0, 1e-7);
  EXPECT_NEAR(bound(6), 3 * 1.0, 1e-7);
}

// Cells cut off from the goal by structure get an infinite bound.
TEST(LandmarkHeuristic, DisconnectedCellsAreUnbounded) {
  LayeredGrid grid(5, 1, 0);
  grid.at(2, 0) = kStructureValue;
  const LandmarkHeuristic h(grid, StepCosts{1.0, 2.0});
  const LandmarkHeuristic::ToGoal bound = h.Towards(4);
  EXPECT_TRUE(std::isinf(bound(0)));
  EXPECT_NEAR(bound(3), 1.0, 1e-7);
}

}  // namespace
}  // namespace semnav::planning
