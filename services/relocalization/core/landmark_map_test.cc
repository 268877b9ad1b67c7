#include "services/relocalization/core/landmark_map.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "services/common/status/field_error.h"

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
  const auto s = map.Upsert(
      {Make(0, 0, {1, 0, 0}), Make(2, 0, {0, 1, 0}), Make(0, 3, {0.9f, 0.1f, 0})}, MergeParams{});
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

// Every hostile value names its field (ErrorField) and leaves the map as it was.
TEST(RelocLandmarkMapTest, AbsurdValuesNameTheFieldAndChangeNothing) {
  LandmarkMap map = ThreeLandmarks();
  const auto expect_rejected = [&map](std::vector<Landmark> incoming, const std::string& field) {
    const auto s = map.Upsert(std::move(incoming), MergeParams{});
    EXPECT_EQ(s.status().code(), absl::StatusCode::kInvalidArgument) << field;
    EXPECT_EQ(ErrorField(s.status()).value_or(""), field);
    EXPECT_LT(s.status().message().size(), 1024u);
    EXPECT_EQ(map.revision(), 1u) << field;
    EXPECT_EQ(map.landmarks().size(), 3u) << field;
  };
  const Landmark good = Make(5, 5, {0, 0, 1});
  Landmark bad = good;
  bad.position.z() = 1e300;  // finite, but no place in any map
  expect_rejected({good, bad}, "landmarks[1].position.z");
  bad = good;
  bad.position.x() = std::numeric_limits<double>::quiet_NaN();
  expect_rejected({bad}, "landmarks[0].position.x");
  bad = good;
  bad.position.y() = -1.0001e5;  // just beyond kMaxCoordinateM
  expect_rejected({bad}, "landmarks[0].position.y");
  bad = good;
  bad.scale = 1e300;
  expect_rejected({bad}, "landmarks[0].scale_m");
  bad = good;
  bad.scale = 0.0;
  expect_rejected({bad}, "landmarks[0].scale_m");
  bad = good;
  bad.descriptor[1] = 3e38f;  // finite float whose square overflows
  expect_rejected({bad}, "landmarks[0].embedding");
  bad = good;
  bad.observations = 4000000000u;  // two of these would wrap a uint32 sum when merged
  expect_rejected({bad}, "landmarks[0].observations");
  expect_rejected(std::vector<Landmark>(kMaxLandmarksPerRequest + 1, good), "landmarks");

  // Exactly at the limits is accepted.
  Landmark edge = good;
  edge.position = {1e5, -1e5, 0.0};
  edge.scale = kMaxLandmarkScaleM;
  edge.observations = kMaxObservations;
  EXPECT_TRUE(map.Upsert({edge}, MergeParams{}).ok());
}

TEST(RelocLandmarkMapTest, OverlongEmbeddingIsRejectedOnAnEmptyMap) {
  LandmarkMap map;
  const auto s = map.Upsert({Make(0, 0, Descriptor(kMaxDescriptorDim + 1, 0.5f))}, MergeParams{});
  EXPECT_EQ(s.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(s.status()).value_or(""), "landmarks[0].embedding");
  EXPECT_TRUE(map.landmarks().empty());
}

TEST(RelocLandmarkMapTest, UnknownIdIsNotFoundNamingTheId) {
  LandmarkMap map = ThreeLandmarks();
  Landmark l = Make(1, 1, {1, 0, 0});
  l.id = 99;
  const auto s = map.Upsert({l}, MergeParams{});
  EXPECT_EQ(s.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(ErrorField(s.status()).value_or(""), "landmarks[0].id");
  EXPECT_EQ(ErrorReason(s.status()).value_or(""), "LANDMARK_NOT_FOUND");
}

}  // namespace
}  // namespace semnav::relocalization
