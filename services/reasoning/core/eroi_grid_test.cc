#include "services/reasoning/core/eroi_grid.h"

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

// The seed's outdoor experiment: delta 3 m, min (-5, -20, 0).
EroiGrid SeedGrid() {
  EroiGridSpec spec;
  spec.min = Eigen::Vector3d(-5.0, -20.0, 0.0);
  spec.delta = 3.0;
  spec.nx = 15;
  spec.ny = 15;
  spec.nz = 2;
  return *EroiGrid::Create(spec);
}

TEST(GatewayEroiGridTest, SeedExampleG5AIsThirteenMinusEightZero) {
  const EroiGrid grid = SeedGrid();
  absl::StatusOr<Eigen::Vector3d> point = grid.Decode("G5A");
  ASSERT_TRUE(point.ok()) << point.status();
  EXPECT_DOUBLE_EQ(point->x(), 13.0);
  EXPECT_DOUBLE_EQ(point->y(), -8.0);
  EXPECT_DOUBLE_EQ(point->z(), 0.0);
  EXPECT_EQ(grid.Encode(Eigen::Vector3d(13.0, -8.0, 0.0)), "G5A");
  EXPECT_EQ(grid.Encode(Eigen::Vector3d(-5.0, -20.0, 0.0)), "A1A");  // the seed's "A1A" = p_min
  EXPECT_EQ(grid.Encode(grid.Centre(EroiIndex{3, 11, 2})), "D12C");
}

TEST(GatewayEroiGridTest, EveryCentreRoundTrips) {
  const EroiGrid grid = SeedGrid();
  for (int flat = 0; flat < grid.size(); ++flat) {
    const Eigen::Vector3d centre = grid.Centre(flat);
    absl::StatusOr<Eigen::Vector3d> back = grid.Decode(grid.Encode(centre));
    ASSERT_TRUE(back.ok()) << grid.Encode(centre);
    EXPECT_TRUE(back->isApprox(centre)) << grid.Encode(centre);
    EXPECT_EQ(grid.Flatten(grid.Unflatten(flat)), flat);
  }
}

TEST(GatewayEroiGridTest, MalformedOrOffGridCodesAreRejected) {
  const EroiGrid grid = SeedGrid();
  for (const char* code : {"", "G5", "55A", "GXA", "Z5A", "G0A", "G17A", "G5D"}) {
    EXPECT_EQ(grid.Decode(code).status().code(), absl::StatusCode::kInvalidArgument) << code;
  }
  EXPECT_TRUE(grid.Decode("g5a").ok());
}

TEST(GatewayEroiGridTest, NeighbourhoodOfRadiusDeltaIsTheCentreAndItsFaces) {
  const EroiGrid grid = SeedGrid();
  EXPECT_EQ(grid.Neighbourhood(Eigen::Vector3d(13.0, -8.0, 3.0), 3.0).size(), 7u);
  EXPECT_EQ(grid.Neighbourhood(Eigen::Vector3d(-5.0, -20.0, 0.0), 3.0).size(), 4u);  // corner
  EXPECT_EQ(grid.size(), 16 * 16 * 3);
}

TEST(GatewayEroiGridTest, GridOverAreaCoversItWithinTheLetters) {
  EroiGridSpec base;
  base.delta = 2.0;
  base.min.z() = 1.0;
  base.nz = 1;
  // 10 x 8 m from (0, 0): centres 1, 3, ..., 9 and 1, ..., 7 -> nx 4, ny 3; z untouched.
  const EroiGridSpec small = GridOverArea(base, {0, 0}, {10, 8});
  EXPECT_DOUBLE_EQ(small.delta, 2.0);
  EXPECT_TRUE(small.min.isApprox(Eigen::Vector3d(1, 1, 1)));
  EXPECT_EQ(small.nx, 4);
  EXPECT_EQ(small.ny, 3);
  EXPECT_EQ(small.nz, 1);
  // 65 m (seed 000's river scene) needs 33 edges of 2 m: the edge widens to 65 / 26 = 2.5 m.
  const EroiGridSpec wide = GridOverArea(base, {0, 0}, {65, 47});
  EXPECT_DOUBLE_EQ(wide.delta, 2.5);
  EXPECT_EQ(wide.nx, 25);
  EXPECT_EQ(wide.ny, 18);  // ceil(47 / 2.5) = 19 centres
  EXPECT_TRUE(EroiGrid::Create(wide).ok());
}

TEST(GatewayEroiGridTest, CreateValidatesTheSpec) {
  EroiGridSpec spec;
  spec.delta = 0.0;
  EXPECT_EQ(EroiGrid::Create(spec).status().code(), absl::StatusCode::kInvalidArgument);
  spec.delta = 1.0;
  spec.nx = 26;
  EXPECT_EQ(EroiGrid::Create(spec).status().code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace semnav::reasoning
