#include "services/common/storage/durable_file.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace semnav::storage {
namespace {

std::string FreshDirectory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(Crc32Test, MatchesTheStandardCheckValue) { EXPECT_EQ(Crc32("123456789"), 0xCBF43926u); }

TEST(WriteFileAtomicallyTest, ReplacesTheWholeFileAndLeavesNoTemporary) {
  const std::string dir = FreshDirectory("durable_replace");
  const std::string path = dir + "/state";
  ASSERT_TRUE(WriteFileAtomically(path, "first version, longer").ok());
  ASSERT_TRUE(WriteFileAtomically(path, "second").ok());
  EXPECT_EQ(*ReadWholeFile(path), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);
}

TEST(WriteFileAtomicallyTest, AMissingDirectoryFailsAndKeepsNothing) {
  const std::string dir = FreshDirectory("durable_missing");
  EXPECT_FALSE(WriteFileAtomically(dir + "/no/such/dir/state", "x").ok());
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(RemoveFileDurablyTest, RemovesOnceThenIsNotFound) {
  const std::string path = FreshDirectory("durable_remove") + "/state";
  ASSERT_TRUE(WriteFileAtomically(path, "x").ok());
  EXPECT_TRUE(RemoveFileDurably(path).ok());
  EXPECT_FALSE(std::filesystem::exists(path));
  EXPECT_TRUE(absl::IsNotFound(RemoveFileDurably(path)));
}

TEST(ReadWholeFileTest, AMissingFileIsNotFound) {
  EXPECT_TRUE(absl::IsNotFound(ReadWholeFile(FreshDirectory("durable_read") + "/absent").status()));
}

TEST(ChecksumFrameTest, RoundTripsBinaryPayloads) {
  const std::string payload("a\0b\xff", 4);
  const std::string file = FrameWithChecksum("MAGIC\n", payload);
  EXPECT_EQ(file.size(), 6u + 8u + 4u + 4u);
  EXPECT_EQ(*PayloadOfFrame("MAGIC\n", file, "test file"), payload);
}

// The framed write gives the same bytes as writing FrameWithChecksum whole.
TEST(ChecksumFrameTest, AFramedWriteIsTheFrameByteForByte) {
  const std::string dir = FreshDirectory("durable_framed");
  const std::string payload("map\0bytes\xfe", 10);
  ASSERT_TRUE(WriteFramedFileAtomically(dir + "/framed", "MAGIC\n", payload).ok());
  EXPECT_EQ(*ReadWholeFile(dir + "/framed"), FrameWithChecksum("MAGIC\n", payload));
  EXPECT_EQ(*PayloadOfFrame("MAGIC\n", *ReadWholeFile(dir + "/framed"), "f"), payload);
  ASSERT_TRUE(WriteFileAtomically(dir + "/pieces", {"ab", "", "cd"}).ok());
  EXPECT_EQ(*ReadWholeFile(dir + "/pieces"), "abcd");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            2);
}

TEST(ChecksumFrameTest, NamesEachKindOfDamage) {
  const std::string file = FrameWithChecksum("MAGIC\n", "payload");
  const auto message = [](const absl::StatusOr<std::string>& r) {
    return std::string(r.status().message());
  };
  EXPECT_EQ(message(PayloadOfFrame("OTHER\n", file, "f")), "f has no valid header");
  EXPECT_EQ(message(PayloadOfFrame("MAGIC\n", file.substr(0, file.size() - 2), "f")),
            "f is truncated (5 of 7 payload bytes)");
  std::string flipped = file;
  flipped.back() ^= 0x01;
  EXPECT_EQ(message(PayloadOfFrame("MAGIC\n", flipped, "f")), "f fails its checksum");
  EXPECT_TRUE(absl::IsDataLoss(PayloadOfFrame("MAGIC\n", "MAG", "f").status()));
}

}  // namespace
}  // namespace semnav::storage
