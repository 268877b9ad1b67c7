#include "services/planning/core/nearest_cell.h"

#include <gtest/gtest.h>

namespace semnav::planning {
namespace {

TEST(NearestCellWithin, TheCentreWhenItIsAccepted) {
  EXPECT_EQ(NearestCellWithin({3, 4}, 2.0, [](Cell) { return true; }), (Cell{3, 4}));
}

TEST(NearestCellWithin, EquallyNearCellsGoToTheFirstInRowOrder) {
  // The four 4-neighbours of (5, 5) are 1 cell away; (5, 4) has the lowest row.
  const auto not_centre = [](Cell c) { return !(c == Cell{5, 5}); };
  EXPECT_EQ(NearestCellWithin({5, 5}, 3.0, not_centre), (Cell{5, 4}));
}

TEST(NearestCellWithin, TheTieKeyRanksEquallyNearCells) {
  // Same candidates; preferring the larger x picks (6, 5), one cell east.
  const auto not_centre = [](Cell c) { return !(c == Cell{5, 5}); };
  EXPECT_EQ(NearestCellWithin({5, 5}, 3.0, not_centre, [](Cell c) { return long{-c.x}; }),
            (Cell{6, 5}));
}

TEST(NearestCellWithin, ANearerCellBeatsABetterTieKey) {
  // (7, 5) is accepted at distance 2 and (5, 4) at distance 1: distance decides first.
  const auto two_cells = [](Cell c) { return c == Cell{7, 5} || c == Cell{5, 4}; };
  EXPECT_EQ(NearestCellWithin({5, 5}, 3.0, two_cells, [](Cell c) { return long{-c.x}; }),
            (Cell{5, 4}));
}

TEST(NearestCellWithin, TheRadiusIsEuclidean) {
  // The diagonal (6, 6) is sqrt(2) = 1.41 cells away: outside 1.4, inside 1.5.
  const auto diagonal = [](Cell c) { return c == Cell{6, 6}; };
  EXPECT_FALSE(NearestCellWithin({5, 5}, 1.4, diagonal).has_value());
  EXPECT_EQ(NearestCellWithin({5, 5}, 1.5, diagonal), (Cell{6, 6}));
}

TEST(NearestCellWithin, NothingAcceptedIsNullopt) {
  EXPECT_FALSE(NearestCellWithin({0, 0}, 4.0, [](Cell) { return false; }).has_value());
  EXPECT_FALSE(NearestCellWithin({0, 0}, -1.0, [](Cell) { return true; }).has_value());
}

}  // namespace
}  // namespace semnav::planning
