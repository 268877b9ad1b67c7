#include "services/common/config/config_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace semnav {
namespace {

using ::testing::HasSubstr;

TEST(ConfigReaderTest, ReadsValuesAndKeepsDefaultsForAbsentKeys) {
  auto reader = ConfigReader::FromString("a: 2.5\nb: hello\nnested: {n: 7, list: [1, 2]}\n");
  ASSERT_TRUE(reader.ok());
  double a = 0;
  std::string b;
  int missing = 42;
  int n = 0;
  std::vector<int> list;
  reader->Read("a", &a).Read("b", &b).Read("missing", &missing);
  ConfigReader nested = reader->Child("nested");
  nested.Read("n", &n).Read("list", &list);
  EXPECT_TRUE(reader->Finish().ok()) << reader->Finish();
  EXPECT_EQ(a, 2.5);
  EXPECT_EQ(b, "hello");
  EXPECT_EQ(missing, 42);
  EXPECT_EQ(n, 7);
  EXPECT_EQ(list, (std::vector<int>{1, 2}));
}

TEST(ConfigReaderTest, UnknownKeyIsNamedWithItsPath) {
  auto reader = ConfigReader::FromString("server: {listen: x, lisen: y}\n");
  ASSERT_TRUE(reader.ok());
  std::string listen;
  reader->Child("server").Read("listen", &listen);
  absl::Status status = reader->Finish();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("server.lisen: unknown key"));
}

// Found by tests/fuzz (service_config): a non-scalar key made Finish() throw.
TEST(ConfigReaderTest, NonScalarKeyIsAnUnknownKeyNotAnException) {
  auto reader = ConfigReader::FromString("mapping: {[1]: 2}\n");
  ASSERT_TRUE(reader.ok());
  ConfigReader mapping = reader->Child("mapping");
  EXPECT_EQ(mapping.Keys(), std::vector<std::string>{"[1]"});
  absl::Status status = reader->Finish();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("mapping.[1]: unknown key"));
}

TEST(ConfigReaderTest, BadTypeAndFailedCheckAreNamed) {
  auto reader = ConfigReader::FromString("mapping: {resolution_m: fast, max_range_m: -1}\n");
  ASSERT_TRUE(reader.ok());
  double resolution = 0.05;
  double range = 8;
  ConfigReader mapping = reader->Child("mapping");
  mapping.Read("resolution_m", &resolution).Read("max_range_m", &range);
  mapping.Check(range > 0, "max_range_m", "must be > 0");
  absl::Status status = reader->Finish();
  EXPECT_THAT(status.message(), HasSubstr("mapping.resolution_m: has the wrong type"));
  EXPECT_THAT(status.message(), HasSubstr("mapping.max_range_m: must be > 0"));
  EXPECT_EQ(resolution, 0.05);  // the default survives a bad value
}

TEST(ConfigReaderTest, ItemsAndKeysGivePathsForLists) {
  auto reader = ConfigReader::FromString("backends: [{name: a}, {name: b, bogus: 1}]\n");
  ASSERT_TRUE(reader.ok());
  std::vector<std::string> names;
  for (ConfigReader& item : reader->Items("backends")) {
    std::string name;
    item.Read("name", &name);
    names.push_back(name);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"a", "b"}));
  EXPECT_THAT(reader->Finish().message(), HasSubstr("backends[1].bogus: unknown key"));
}

TEST(ConfigReaderTest, SubtreeIsHandedOnAsYamlWithoutKeyChecks) {
  auto reader = ConfigReader::FromString("settings: {gateway: {mapping: {address: 'h:1'}}}\n");
  ASSERT_TRUE(reader.ok());
  std::string yaml = "untouched";
  std::string absent = "untouched";
  reader->ReadSubtree("settings", &yaml).ReadSubtree("absent", &absent);
  EXPECT_TRUE(reader->Finish().ok()) << reader->Finish();
  EXPECT_EQ(absent, "untouched");
  auto again = ConfigReader::FromString(yaml);
  ASSERT_TRUE(again.ok());
  std::string address;
  again->Child("gateway").Child("mapping").Read("address", &address);
  EXPECT_EQ(address, "h:1");
}

TEST(ConfigReaderTest, MissingFileIsNotFoundAndBadYamlIsInvalid) {
  EXPECT_EQ(ConfigReader::FromFile("/nonexistent/semnav.yaml").status().code(),
            absl::StatusCode::kNotFound);
  EXPECT_EQ(ConfigReader::FromString("a: [1, 2").status().code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(ConfigReaderTest, NonMappingSectionIsAnError) {
  auto reader = ConfigReader::FromString("server: 5\n");
  ASSERT_TRUE(reader.ok());
  reader->Child("server");
  EXPECT_THAT(reader->Finish().message(), HasSubstr("server: must be a mapping"));
}

}  // namespace
}  // namespace semnav
