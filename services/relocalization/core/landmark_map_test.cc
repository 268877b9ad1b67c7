#include "services/relocalization/core/landmark_map.h"

#include <limits>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

Landmark Make(double x, double y, Descriptor d, double scale = 0.5) {
  Landmark l;
  l.position = {x, y, 0.0};
  l.scale = scale;
  l.descriptor = std::move(d);
  return l;
}

LandmarkMap ThreeLandmarks() {
  LandmarkMap map;
  const auto s = map.Upsert({Make(0, 0, {1, 0, 0}), Make(2, 0, {0, 1, 0}), Make(0, 3, {0.9f, 0.1f, 0})},
                            MergeParams{});
  EXPECT_TRUE(s.ok());
  return map;
}

TEST(RelocLandmarkMapTest, InsertAssignsIdsAndIndexesByLabel) {
  const LandmarkMap map = ThreeLandmarks();
  ASSERT_EQ(map.landmarks().size(), 3u);
  EXPECT_EQ(map.landmarks()[0].id, 1u);
  EXPECT_EQ(map.landmarks()[2].id, 3u);
  EXPECT_EQ(map.revision(), 1u);
  EXPECT_EQ(map.descriptor_dim(), 3u);
  EXPECT_EQ(map.index()->WithLabel(0), (std::vector<size_t>{0, 2}));
  EXPECT_EQ(map.index()->WithLabel(1), (std::vector<size_t>{1}));
  EXPECT_TRUE(map.index()->WithLabel(2).empty());
  EXPECT_EQ(map.index()->Neighbourhood(0, 1), (std::vector<size_t>{1}));
}

TEST(RelocLandmarkMapTest, SameObjectMergesByObservationWeight) {
  LandmarkMap map = ThreeLandmarks();
  Landmark again = Make(0.2, 0, {1, 0, 0}, 0.8);
  again.observations = 3;
  const auto s = map.Upsert({again}, MergeParams{});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->merged, 1u);
  EXPECT_EQ(s->inserted, 0u);
  EXPECT_EQ(s->ids, (std::vector<uint64_t>{1}));
  const Landmark& merged = map.landmarks()[0];
  EXPECT_EQ(merged.id, 1u);
  EXPECT_EQ(merged.observations, 4u);
  EXPECT_NEAR(merged.position.x(), 0.15, 1e-12);  // (1 * 0 + 3 * 0.2) / 4
  EXPECT_NEAR(merged.scale, 0.725, 1e-12);        // (0.5 + 3 * 0.8) / 4
}

TEST(RelocLandmarkMapTest, DifferentLabelNearbyIsANewLandmark) {
  LandmarkMap map = ThreeLandmarks();
  const auto s = map.Upsert({Make(0.1, 0, {0, 0, 1})}, MergeParams{});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->inserted, 1u);
  EXPECT_EQ(map.landmarks().back().id, 4u);
}

TEST(RelocLandmarkMapTest, KnownIdIsReplaced) {
  LandmarkMap map = ThreeLandmarks();
  Landmark moved = Make(5, 5, {0, 1, 0});
  moved.id = 2;
  const auto s = map.Upsert({moved}, MergeParams{});
  ASSERT_TRUE(s.ok());
  EXPECT_EQ(s->replaced, 1u);
  EXPECT_EQ(map.landmarks()[1].position, Eigen::Vector3d(5, 5, 0));
  EXPECT_EQ(map.index()->tree().Nearest({5, 5, 0}, 1), (std::vector<size_t>{1}));
}

TEST(RelocLandmarkMapTest, BadInputNamesTheFieldAndChangesNothing) {
  LandmarkMap map = ThreeLandmarks();
  Landmark unknown = Make(1, 1, {1, 0, 0});
  unknown.id = 99;
  auto s = map.Upsert({Make(9, 9, {1, 0, 0}), unknown}, MergeParams{});
  EXPECT_EQ(s.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(s.status().message(), HasSubstr("landmarks[1].id"));

  s = map.Upsert({Make(9, 9, {1, 0, 0}), Make(1, 1, {1, 0})}, MergeParams{});
  EXPECT_EQ(s.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(s.status().message(), HasSubstr("landmarks[1].embedding"));

  s = map.Upsert({Make(std::numeric_limits<double>::infinity(), 0, {1, 0, 0})}, MergeParams{});
  EXPECT_EQ(s.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(s.status().message(), HasSubstr("landmarks[0].position"));

  s = map.Upsert({Make(0, 0, {1, 0, 0}, 0.0)}, MergeParams{});
  EXPECT_THAT(s.status().message(), HasSubstr("landmarks[0].scale"));

  s = map.Upsert({}, MergeParams{});
  EXPECT_EQ(s.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(s.status().message(), HasSubstr("landmarks"));

  EXPECT_EQ(map.revision(), 1u);
  EXPECT_EQ(map.landmarks().size(), 3u);
  EXPECT_EQ(map.next_id(), 4u);
}

}  // namespace
}  // namespace semnav::relocalization
