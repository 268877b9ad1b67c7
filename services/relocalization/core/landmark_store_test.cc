#include "services/relocalization/core/landmark_store.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "services/common/status/field_error.h"

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

std::string FreshDir(const std::string& name) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / ("reloc_store_" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

std::vector<Landmark> OneLandmark(double x) {
  Landmark l;
  l.position = {x, 0.0, 0.0};
  l.scale = 0.5;
  l.descriptor = {1.0f, 0.0f};
  return {l};
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RelocLandmarkStoreTest, MapIdsAreValidatedAndUnknownIdsNotFound) {
  auto store = LandmarkStore::Open("", MergeParams{});
  ASSERT_TRUE(store.ok());
  auto get = (*store)->Get("nope");
  EXPECT_EQ(get.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(get.status().message(), HasSubstr("map_id"));
  for (const char* bad : {"", "../etc", ".hidden", "a/b", "sp ace"}) {
    auto up = (*store)->Upsert(bad, OneLandmark(0));
    EXPECT_EQ(up.status().code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(up.status().message(), HasSubstr("map_id"));
  }
  EXPECT_EQ((*store)->Delete("nope").code(), absl::StatusCode::kNotFound);
}

TEST(RelocLandmarkStoreTest, UpsertGetDelete) {
  auto store = LandmarkStore::Open("", MergeParams{});
  ASSERT_TRUE(store.ok());
  ASSERT_TRUE((*store)->Upsert("robot-a", OneLandmark(0)).ok());
  const auto before = (*store)->Get("robot-a");
  ASSERT_TRUE(before.ok());
  ASSERT_TRUE((*store)->Upsert("robot-a", OneLandmark(5)).ok());
  EXPECT_EQ((*before)->landmarks().size(), 1u);  // snapshots never change
  EXPECT_EQ((*(*store)->Get("robot-a"))->landmarks().size(), 2u);
  ASSERT_TRUE((*store)->Delete("robot-a").ok());
  EXPECT_EQ((*store)->Get("robot-a").status().code(), absl::StatusCode::kNotFound);
}

TEST(RelocLandmarkStoreTest, PersistsAcrossReopen) {
  const std::string dir = FreshDir("reopen");
  {
    auto store = LandmarkStore::Open(dir, MergeParams{});
    ASSERT_TRUE(store.ok());
    ASSERT_TRUE((*store)->Upsert("m1", OneLandmark(1)).ok());
    ASSERT_TRUE((*store)->Upsert("m1", OneLandmark(7)).ok());
  }
  auto store = LandmarkStore::Open(dir, MergeParams{});
  ASSERT_TRUE(store.ok());
  const auto map = (*store)->Get("m1");
  ASSERT_TRUE(map.ok());
  EXPECT_EQ((*map)->revision(), 2u);
  ASSERT_EQ((*map)->landmarks().size(), 2u);
  EXPECT_EQ((*map)->landmarks()[1].position.x(), 7.0);
}

TEST(RelocLandmarkStoreTest, CorruptFileIsDataLossAndNeverOverwritten) {
  const std::string dir = FreshDir("corrupt");
  {
    auto store = LandmarkStore::Open(dir, MergeParams{});
    ASSERT_TRUE(store.ok());
    ASSERT_TRUE((*store)->Upsert("good", OneLandmark(1)).ok());
    ASSERT_TRUE((*store)->Upsert("bad", OneLandmark(2)).ok());
  }
  const std::string bad_path = dir + "/bad.lmap";
  std::filesystem::resize_file(bad_path, std::filesystem::file_size(bad_path) - 4);
  const std::string corrupt_bytes = ReadAll(bad_path);

  auto store = LandmarkStore::Open(dir, MergeParams{});
  ASSERT_TRUE(store.ok());
  EXPECT_TRUE((*store)->Get("good").ok());
  EXPECT_EQ((*store)->Get("bad").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ((*store)->Upsert("bad", OneLandmark(3)).status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(ReadAll(bad_path), corrupt_bytes);

  ASSERT_TRUE((*store)->Delete("bad").ok());  // the explicit way out
  EXPECT_FALSE(std::filesystem::exists(bad_path));
  EXPECT_TRUE((*store)->Upsert("bad", OneLandmark(3)).ok());
}

TEST(RelocLandmarkStoreTest, AHugeMapIdIsNamedButNotEchoed) {
  auto store = LandmarkStore::Open("", MergeParams{});
  ASSERT_TRUE(store.ok());
  const std::string huge(1 << 20, 'a');
  const auto upsert = (*store)->Upsert(huge, OneLandmark(0.0));
  EXPECT_EQ(upsert.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(upsert.status()).value_or(""), "map_id");
  EXPECT_LT(upsert.status().message().size(), 200u);
  EXPECT_EQ((*store)->Get(huge).status().message(), upsert.status().message());
}

}  // namespace
}  // namespace semnav::relocalization
