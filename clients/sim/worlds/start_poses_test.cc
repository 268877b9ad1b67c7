#include "clients/sim/worlds/start_poses.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/test_worlds.h"
#include "clients/sim/core/world_yaml.h"

namespace semnav::sim {
namespace {

TEST(SimStartPosesTest, StartsStayWhereTheFilterAllowsAndApart) {
  const World world = testing::OpenWorld();  // 10 x 10 m, free
  Rng rng(5);
  // Only the eastern strip x > 2 (an OctoMap world passes "the scan saw floor here").
  const std::vector<StartPose> starts = ChooseStarts(
      world, Modality::kGround, 0.0, 4, rng, [](const Eigen::Vector2d& p) { return p.x() > 2.0; });
  ASSERT_EQ(starts.size(), 4u);
  for (size_t i = 0; i < starts.size(); ++i) {
    EXPECT_GT(starts[i].position.x(), 2.0);
    for (size_t j = 0; j < i; ++j) EXPECT_GE((starts[i].position - starts[j].position).norm(), 1.5);
  }
  // Nothing allowed: no starts rather than starts anywhere.
  Rng again(5);
  EXPECT_TRUE(ChooseStarts(world, Modality::kGround, 0.0, 4, again, [](const Eigen::Vector2d&) {
                return false;
              }).empty());
}

// A 10 x 10 m hall (raster cells at 0.1 m from the origin) with one wall along y at x 4.02-4.22
// and, in the second test, a 0.6 m alcove beside it, open to the south.
World HallWith(const std::vector<BoxShape>& walls) {
  World world;
  world.name = "hall";
  world.bounds_max = Eigen::Vector2d(10, 10);
  for (const BoxShape& wall : walls) world.obstacles.push_back(Obstacle{"wall", Rgb{}, wall});
  return world;
}

TEST(SimStartPosesTest, StartWithoutClearanceMovesToTheNearestClearCellAndAClearOneStays) {
  // Wall faces at x = 4.02 and 4.22; clearance = 0.25 m radius + 0.1 m margin = 0.35 m.
  const World world = HallWith({testing::Box(4.12, 5.0, 0.2, 4.0, 1.0)});
  const StartClearanceSearch search(world, Modality::kGround, 0.0, StartClearance{});
  // 0.27 m from the face: one cell west (3.65, 0.37 m) is the nearest with clearance.
  const Eigen::Vector2d near_wall(3.75, 5.05);
  EXPECT_FALSE(search.Clear(near_wall));
  const std::optional<Eigen::Vector2d> moved = search.Nearest(near_wall);
  ASSERT_TRUE(moved.has_value());
  EXPECT_NEAR(moved->x(), 3.65, 1e-9);
  EXPECT_NEAR(moved->y(), 5.05, 1e-9);
  // 1.37 m from the face: stays exactly where it was drawn.
  const Eigen::Vector2d open(2.65, 5.05);
  ASSERT_TRUE(search.Nearest(open).has_value());
  EXPECT_EQ(*search.Nearest(open), open);
  // With no margin 0.27 m is clearance enough (the body's 0.25 m radius only).
  const StartClearanceSearch bare(world, Modality::kGround, 0.0, StartClearance{0.0});
  EXPECT_EQ(*bare.Nearest(near_wall), near_wall);
}

TEST(SimStartPosesTest, StartInAPocketLeavesItByItsMouthNotThroughTheWall) {
  // Alcove x 4.22-4.82 (0.6 m: at most 0.3 m from a wall, never 0.35), y 4.02-6.02, open to the
  // south; its west wall is 0.2 m thick with the open hall behind it.
  const World world =
      HallWith({testing::Box(4.12, 5.02, 0.2, 2.0, 1.0), testing::Box(4.92, 5.02, 0.2, 2.0, 1.0),
                testing::Box(4.52, 6.12, 1.0, 0.2, 1.0)});
  const StartClearanceSearch search(world, Modality::kGround, 0.0, StartClearance{});
  const Eigen::Vector2d in_pocket(4.55, 5.45);  // 0.33 m west, 0.27 m east
  EXPECT_FALSE(search.Clear(in_pocket));
  // Behind the west wall (3.65, 5.45) is clear and 0.9 m away in a straight line, but the
  // robot would have to pass through the wall. Down the alcove's only free column (x 4.55) and
  // out of its mouth, the first clear cell is (4.55, 3.75), 17 steps: 0.382 m from the east
  // wall's corner (4.82, 4.02); (4.55, 3.85) is 0.319 m from it, and the cells beside those
  // (4.45 / 4.65, 3.85) 0.286 m and 0.240 m from a corner.
  EXPECT_TRUE(search.Clear({3.65, 5.45}));
  const std::optional<Eigen::Vector2d> moved = search.Nearest(in_pocket);
  ASSERT_TRUE(moved.has_value());
  EXPECT_NEAR(moved->x(), 4.55, 1e-9);
  EXPECT_NEAR(moved->y(), 3.75, 1e-9);
  // A filter that forbids the hall south of y = 3.8 leaves no allowed clear cell nearer than
  // out of the mouth and round the walls: the move respects it.
  const StartClearanceSearch north_only(world, Modality::kGround, 0.0, StartClearance{},
                                        [](const Eigen::Vector2d& p) { return p.y() > 3.8; });
  const std::optional<Eigen::Vector2d> allowed = north_only.Nearest(in_pocket);
  ASSERT_TRUE(allowed.has_value());
  EXPECT_GT(allowed->y(), 3.8);
  EXPECT_TRUE(north_only.Clear(*allowed));
}

TEST(SimStartPosesTest, StartInARoomWithANarrowDoorMovesOutThroughTheDoor) {
  // A 2 x 2 m room (inside x, y 6.02-8.02) in the hall; its south wall's door is 0.66 m wide
  // (x 6.72-7.38). On the 0.1 m raster the door leaves one column (x 7.05, 0.3 m from the cells
  // the jambs cover) free for the 0.25 m radius but none for radius + margin (0.35 m): the room
  // is joined to the hall for the robot, but at radius + margin it is an island of its own, about
  // 1.3 x 1.3 m, under the 1.5 m island radius.
  const World world = HallWith({testing::Box(5.92, 7.02, 0.2, 2.4, 1.0),     // west
                                testing::Box(8.12, 7.02, 0.2, 2.4, 1.0),     // east
                                testing::Box(7.02, 8.12, 2.4, 0.2, 1.0),     // north
                                testing::Box(6.27, 5.92, 0.9, 0.2, 1.0),     // south, x 5.82-6.72
                                testing::Box(7.80, 5.92, 0.84, 0.2, 1.0)});  // x 7.38-8.22
  const StartClearanceSearch search(world, Modality::kGround, 0.0, StartClearance{});
  // The room's centre is 0.95 m from every wall, but in the pocket.
  const Eigen::Vector2d in_room(7.05, 7.05);
  EXPECT_FALSE(search.Clear(in_room));
  // Down the door column and out: (7.05, 5.75) is 0.337 m from the jamb corner (7.38, 5.82);
  // (7.05, 5.65) is 0.371 m, 14 steps; the cells beside (6.95 / 7.15, 5.75) are 0.22 m from the
  // cells the jambs cover.
  const std::optional<Eigen::Vector2d> moved = search.Nearest(in_room);
  ASSERT_TRUE(moved.has_value());
  EXPECT_NEAR(moved->x(), 7.05, 1e-9);
  EXPECT_NEAR(moved->y(), 5.65, 1e-9);
  // With a 1.2 m door (x 6.42-7.62) the room is part of the hall for radius + margin too: the
  // start stays put.
  const World wide =
      HallWith({testing::Box(5.92, 7.02, 0.2, 2.4, 1.0), testing::Box(8.12, 7.02, 0.2, 2.4, 1.0),
                testing::Box(7.02, 8.12, 2.4, 0.2, 1.0),
                testing::Box(6.12, 5.92, 0.6, 0.2, 1.0),    // x 5.82-6.42
                testing::Box(7.92, 5.92, 0.6, 0.2, 1.0)});  // x 7.62-8.22
  const StartClearanceSearch wide_search(wide, Modality::kGround, 0.0, StartClearance{});
  EXPECT_EQ(*wide_search.Nearest(in_room), in_room);
}

// Hand-drawn starts are used as they are (no draw, no move): each must already have the
// clearance a generated start gets.
void ExpectDrawnStartsClear(const std::string& folder, const std::vector<std::string>& names,
                            size_t starts_per_world) {
  for (const std::string& name : names) {
    const absl::StatusOr<World> world = LoadWorldFile(
        absl::StrCat(SEMNAV_SOURCE_DIR, "/tests/worlds/", folder, "/", name, ".yaml"));
    ASSERT_TRUE(world.ok()) << world.status();
    if (starts_per_world > 0) {
      EXPECT_EQ(world->starts.size(), starts_per_world) << name;
    }
    for (const StartPose& start : world->starts) {
      const StartClearanceSearch search(*world, start.modality, start.position.z(),
                                        StartClearance{});
      EXPECT_TRUE(search.Clear(start.position.head<2>()))
          << name << " start (" << start.position.x() << ", " << start.position.y() << ")";
    }
  }
}

TEST(SimStartPosesTest, HandDrawnWorldStartsHaveClearance) {
  ExpectDrawnStartsClear("hand_drawn",
                         {"clinic", "flat_l_shaped", "office_kitchenette", "storage_room",
                          "yard_parking", "flyroll_storage_ledge"},
                         0);
}

TEST(SimStartPosesTest, HandDrawnHoldoutWorldStartsHaveClearance) {
  ExpectDrawnStartsClear("hand_drawn_holdout",
                         {"clinic_ward", "home_bungalow", "open_office", "warehouse_aisles"}, 3);
  ExpectDrawnStartsClear("hand_drawn_holdout", {"campus_quad"}, 4);
}

TEST(SimStartPosesTest, HandDrawnBlindStartWorldStartsHaveClearance) {
  ExpectDrawnStartsClear("hand_drawn_blind_starts", {"hotel_floor"}, 4);
}

}  // namespace
}  // namespace semnav::sim
