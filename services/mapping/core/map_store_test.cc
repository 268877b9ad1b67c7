#include "services/mapping/core/map_store.h"

#include <filesystem>
#include <fstream>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace semnav::mapping {
namespace {

using ::testing::HasSubstr;

class MapStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = ::testing::TempDir() + "/map_store_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::remove_all(directory_);
  }
  std::string directory_;
};

TEST(Crc32Test, MatchesTheStandardCheckValue) { EXPECT_EQ(Crc32("123456789"), 0xCBF43926u); }

TEST_F(MapStoreTest, SaveLoadListDelete) {
  const MapStore store = *MapStore::Open(directory_);
  ASSERT_TRUE(store.Save("lab", "payload-1").ok());
  ASSERT_TRUE(store.Save("attic", "x").ok());
  EXPECT_EQ(*store.Load("lab"), "payload-1");
  ASSERT_TRUE(store.Save("lab", "payload-2").ok());  // replaced atomically
  EXPECT_EQ(*store.Load("lab"), "payload-2");
  const std::vector<StoredMap> maps = *store.List();
  ASSERT_EQ(maps.size(), 2u);
  EXPECT_EQ(maps[0].map_id, "attic");
  EXPECT_EQ(maps[1].size_bytes, 19u + 9u);  // header + payload
  EXPECT_FALSE(std::filesystem::exists(directory_ + "/lab.snmap.tmp"));
  ASSERT_TRUE(store.Delete("lab").ok());
  EXPECT_EQ(store.Load("lab").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(store.Delete("lab").code(), absl::StatusCode::kNotFound);
}

TEST_F(MapStoreTest, CorruptFileIsDataLoss) {
  const MapStore store = *MapStore::Open(directory_);
  ASSERT_TRUE(store.Save("lab", "some map bytes").ok());
  {
    std::fstream file(directory_ + "/lab.snmap", std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(20);
    file.put('#');  // flip one payload byte
  }
  const absl::Status checksum = store.Load("lab").status();
  EXPECT_EQ(checksum.code(), absl::StatusCode::kDataLoss);
  EXPECT_THAT(std::string(checksum.message()), HasSubstr("checksum"));
  std::filesystem::resize_file(directory_ + "/lab.snmap", 25);
  EXPECT_EQ(store.Load("lab").status().code(), absl::StatusCode::kDataLoss);
  std::ofstream(directory_ + "/junk.snmap") << "not a map";
  EXPECT_EQ(store.Load("junk").status().code(), absl::StatusCode::kDataLoss);
}

TEST_F(MapStoreTest, RejectsBadMapIds) {
  const MapStore store = *MapStore::Open(directory_);
  for (const std::string& id : std::vector<std::string>{"", "../etc", "a b", std::string(65, 'a')}) {
    const absl::Status status = store.Save(id, "x").status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << id;
    EXPECT_THAT(std::string(status.message()), HasSubstr("map_id"));
  }
}

}  // namespace
}  // namespace semnav::mapping
