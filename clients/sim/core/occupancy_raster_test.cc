#include "clients/sim/core/occupancy_raster.h"

#include <gtest/gtest.h>

#include "clients/sim/core/test_worlds.h"

namespace semnav::sim {
namespace {

using testing::Box;

TEST(SimOccupancyRasterTest, BoxCellsAndInflation) {
  World world = testing::OpenWorld();  // 10 x 10 m from (-5, -5)
  world.obstacles.push_back(Obstacle{"furniture", Rgb{}, Box(0.0, 0.0, 1.0, 1.0, 1.0)});
  RasterOptions options;
  options.resolution = 0.1;
  options.robot_radius = 0.0;
  GroundTruthGrid grid = RasterizeOccupancy(world, options);
  ASSERT_EQ(grid.width, 100);
  ASSERT_EQ(grid.height, 100);
  int occupied = 0;
  for (uint8_t c : grid.cells) occupied += c == 100 ? 1 : 0;
  EXPECT_EQ(occupied, 100);  // 1 m^2 at 0.1 m: 10 x 10 cells
  EXPECT_EQ(grid.at(50, 50), 100);
  EXPECT_EQ(grid.at(55, 50), 0);  // centre x = 0.55, outside the half-width 0.5
  options.robot_radius = 0.3;
  grid = RasterizeOccupancy(world, options);
  EXPECT_EQ(grid.at(57, 50), 100);  // 0.25 m beyond the face
  EXPECT_EQ(grid.at(59, 50), 0);    // 0.45 m beyond: free
}

TEST(SimOccupancyRasterTest, HeightBandAndLayers) {
  World world = testing::OpenWorld();
  BoxShape shelf = Box(2.0, 2.0, 1.0, 1.0, 0.5);
  shelf.base_z = 2.0;  // overhead, out of a ground robot's band
  world.obstacles.push_back(Obstacle{"furniture", Rgb{}, shelf});
  world.obstacles.push_back(Obstacle{"furniture", Rgb{}, Box(-2.0, -2.0, 1.0, 1.0, 2.0)});
  world.obstacles.push_back(Obstacle{"wall", Rgb{}, Box(0.0, 4.0, 10.0, 0.2, 1.0)});
  RasterOptions options;
  options.resolution = 0.5;
  options.robot_radius = 0.0;
  const GroundTruthGrid grid = RasterizeOccupancy(world, options);
  EXPECT_EQ(grid.at(14, 14), 0);  // under the shelf (2.25, 2.25)
  EXPECT_EQ(grid.at(6, 6), 100);  // the tall box (-1.75, -1.75)
  const GroundTruthGrid layers = RasterizeHeightLayers(world, 0.5, 4.0);
  EXPECT_EQ(layers.at(6, 6), 50);    // 2 m of a 4 m ceiling: ceil(0.5 * 99)
  EXPECT_EQ(layers.at(0, 18), 100);  // walls are structure however low
  EXPECT_EQ(layers.at(10, 10), 0);
}

}  // namespace
}  // namespace semnav::sim
