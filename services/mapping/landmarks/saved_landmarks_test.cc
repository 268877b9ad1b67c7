#include "services/mapping/landmarks/saved_landmarks.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace semnav::mapping {
namespace {

std::string FreshDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

std::vector<SceneLandmark> TwoLandmarks() {
  std::vector<SceneLandmark> out(2);
  out[0].object_id = 11;
  out[0].landmark.position = Eigen::Vector3d(1, 2, 0.5);
  out[0].landmark.scale = 0.8;
  out[0].landmark.descriptor = {0.0f, 1.0f, 0.3f};
  out[0].landmark.observations = 5;
  out[1].object_id = 12;
  out[1].landmark.position = Eigen::Vector3d(-3, 4, 1.0);
  out[1].landmark.scale = 1.5;
  out[1].landmark.descriptor = {0.9f, 0.1f, 0.0f};
  out[1].landmark.observations = 3;
  return out;
}

TEST(SavedLandmarks, RoundTripUnderTheSameMapId) {
  const std::string dir = FreshDirectory("saved_landmarks_round_trip");
  ASSERT_TRUE(SaveLandmarks(dir, "kitchen", TwoLandmarks()).ok());
  EXPECT_TRUE(std::filesystem::exists(dir + "/kitchen.lmap"));
  absl::StatusOr<relocalization::LandmarkMap> loaded = LoadLandmarks(dir, "kitchen");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  ASSERT_EQ(loaded->landmarks().size(), 2u);
  EXPECT_EQ(loaded->landmarks()[0].id, 1u);
  EXPECT_EQ(loaded->landmarks()[1].id, 2u);
  EXPECT_EQ(loaded->landmarks()[1].position, Eigen::Vector3d(-3, 4, 1.0));
  EXPECT_EQ(loaded->landmarks()[1].scale, 1.5);
  EXPECT_EQ(loaded->landmarks()[0].descriptor, (std::vector<float>{0.0f, 1.0f, 0.3f}));
  EXPECT_EQ(loaded->landmarks()[0].observations, 5u);
  EXPECT_EQ(loaded->next_id(), 3u);
  // Another id is another map.
  EXPECT_TRUE(absl::IsNotFound(LoadLandmarks(dir, "garage").status()));
}

TEST(SavedLandmarks, CorruptFileIsDataLossAndDeleteRemovesIt) {
  const std::string dir = FreshDirectory("saved_landmarks_corrupt");
  ASSERT_TRUE(SaveLandmarks(dir, "hall", TwoLandmarks()).ok());
  {
    std::fstream file(dir + "/hall.lmap", std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(20);
    file.put('\x7f');
  }
  EXPECT_EQ(LoadLandmarks(dir, "hall").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_TRUE(DeleteLandmarks(dir, "hall").ok());
  EXPECT_FALSE(std::filesystem::exists(dir + "/hall.lmap"));
  EXPECT_TRUE(DeleteLandmarks(dir, "hall").ok());  // already gone: nothing to do
}

TEST(SavedLandmarks, EmptySceneSavesAnEmptyMap) {
  const std::string dir = FreshDirectory("saved_landmarks_empty");
  ASSERT_TRUE(SaveLandmarks(dir, "empty", {}).ok());
  absl::StatusOr<relocalization::LandmarkMap> loaded = LoadLandmarks(dir, "empty");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  EXPECT_TRUE(loaded->landmarks().empty());
}

}  // namespace
}  // namespace semnav::mapping
