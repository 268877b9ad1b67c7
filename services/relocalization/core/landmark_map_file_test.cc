#include "services/relocalization/core/landmark_map_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace semnav::relocalization {
namespace {

std::string TempDir(const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("reloc_file_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

LandmarkMap TwoLandmarks() {
  LandmarkMap map;
  Landmark a, b;
  a.position = {1.5, -2.0, 0.25};
  a.scale = 0.4;
  a.descriptor = {0.1f, 0.9f};
  b.position = {3.0, 4.0, 5.0};
  b.scale = 1.2;
  b.descriptor = {0.7f, 0.2f};
  b.observations = 5;
  EXPECT_TRUE(map.Upsert({a, b}, MergeParams{}).ok());
  return map;
}

TEST(RelocLandmarkMapFileTest, RoundTripKeepsEverything) {
  const std::string path = TempDir("roundtrip") + "/m.lmap";
  const LandmarkMap map = TwoLandmarks();
  ASSERT_TRUE(WriteLandmarkMapFile(path, map).ok());
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(path).parent_path())) {
    EXPECT_EQ(entry.path(), path) << "left behind";  // no temporary
  }
  const auto read = ReadLandmarkMapFile(path);
  ASSERT_TRUE(read.ok()) << read.status();
  EXPECT_EQ(read->revision(), 1u);
  EXPECT_EQ(read->next_id(), 3u);
  ASSERT_EQ(read->landmarks().size(), 2u);
  const Landmark& b = read->landmarks()[1];
  EXPECT_EQ(b.id, 2u);
  EXPECT_EQ(b.position, Eigen::Vector3d(3.0, 4.0, 5.0));
  EXPECT_EQ(b.scale, 1.2);
  EXPECT_EQ(b.observations, 5u);
  EXPECT_EQ(b.descriptor, (Descriptor{0.7f, 0.2f}));
  EXPECT_EQ(read->index()->WithLabel(1), (std::vector<size_t>{0}));
}

TEST(RelocLandmarkMapFileTest, FlippedByteIsDataLoss) {
  const std::string path = TempDir("flip") + "/m.lmap";
  ASSERT_TRUE(WriteLandmarkMapFile(path, TwoLandmarks()).ok());
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekp(60);
  f.put('\x7f');
  f.close();
  EXPECT_EQ(ReadLandmarkMapFile(path).status().code(), absl::StatusCode::kDataLoss);
}

TEST(RelocLandmarkMapFileTest, TruncatedIsDataLossAndMissingIsNotFound) {
  const std::string dir = TempDir("trunc");
  const std::string path = dir + "/m.lmap";
  ASSERT_TRUE(WriteLandmarkMapFile(path, TwoLandmarks()).ok());
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 9);
  EXPECT_EQ(ReadLandmarkMapFile(path).status().code(), absl::StatusCode::kDataLoss);
  std::filesystem::resize_file(path, 3);
  EXPECT_EQ(ReadLandmarkMapFile(path).status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(ReadLandmarkMapFile(dir + "/none.lmap").status().code(), absl::StatusCode::kNotFound);
}

}  // namespace
}  // namespace semnav::relocalization
