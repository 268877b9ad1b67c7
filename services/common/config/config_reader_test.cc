#include "services/common/config/config_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "services/common/status/field_error.h"

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

TEST(ConfigReaderTest, RequireNamesAMissingKeyOrSection) {
  auto reader = ConfigReader::FromString("a: 1\nbox: {size: 2}\n");
  ASSERT_TRUE(reader.ok());
  int a = 0;
  int b = 7;
  int size = 0;
  int center = 5;
  reader->Require("a", &a).Require("b", &b);
  reader->RequireChild("box").Require("size", &size);
  // An absent section is one error: its own required keys are not listed on top of it.
  reader->RequireChild("bounds").Require("min", &center);
  const absl::Status status = reader->Finish();
  EXPECT_EQ(status.message(), "config: b: missing; bounds: missing");
  EXPECT_EQ(a, 1);
  EXPECT_EQ(b, 7);
  EXPECT_EQ(size, 2);
  EXPECT_EQ(center, 5);
}

TEST(ConfigReaderTest, ReadsFixedSizeEigenVectors) {
  auto reader = ConfigReader::FromString(
      "center: [1.5, -2]\nsize: [1, 2, 3e2]\nshort: [1, 2]\ninf: [1, .inf]\nword: [1, x]\n"
      "scalar: 4\n");
  ASSERT_TRUE(reader.ok());
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  Eigen::Vector3d short_list(9, 9, 9);
  Eigen::Vector2d inf(9, 9);
  Eigen::Vector2d word(9, 9);
  Eigen::Vector2d scalar(9, 9);
  reader->Read("center", &center).Require("size", &size).Read("short", &short_list);
  reader->Read("inf", &inf).Read("word", &word).Read("scalar", &scalar);
  EXPECT_EQ(reader->Finish().message(),
            "config: short: expected a list of 3 numbers; inf[1]: expected a finite number; "
            "word[1]: expected a finite number; scalar: expected a list of 2 numbers");
  EXPECT_EQ(center, Eigen::Vector2d(1.5, -2));
  EXPECT_EQ(size, Eigen::Vector3d(1, 2, 300));
  // A value that does not read leaves the default whole.
  EXPECT_EQ(short_list, Eigen::Vector3d(9, 9, 9));
  EXPECT_EQ(inf, Eigen::Vector2d(9, 9));
}

TEST(ConfigReaderTest, ReadsListsOfEigenVectors) {
  auto reader = ConfigReader::FromString(
      "polygon: [[0, 0], [1, 0], [1, 1]]\nempty: []\nbroken: [[0, 0], [1], [2, 2, 2]]\n"
      "bad: [[0, 0], [nan_, 1]]\nnot_list: 5\n");
  ASSERT_TRUE(reader.ok());
  std::vector<Eigen::Vector2d> polygon, empty, broken, bad, not_list;
  reader->Require("polygon", &polygon).Read("empty", &empty).Read("broken", &broken);
  reader->Read("bad", &bad).Read("not_list", &not_list);
  // Every bad point of a list is named.
  EXPECT_EQ(reader->Finish().message(),
            "config: broken[1]: expected a list of 2 numbers; broken[2]: expected a list of 2 "
            "numbers; bad[1][0]: expected a finite number; not_list: must be a list");
  ASSERT_EQ(polygon.size(), 3u);
  EXPECT_EQ(polygon[2], Eigen::Vector2d(1, 1));
  EXPECT_TRUE(empty.empty());
  EXPECT_TRUE(broken.empty());
}

TEST(ConfigReaderTest, NullKeepsTheDefaultUnlessTheDocumentForbidsIt) {
  const std::string yaml = "a: ~\nb:\nbox: ~\nlist: ~\nitems: [~, {x: 1}]\n";
  auto config = ConfigReader::FromString(yaml);
  ASSERT_TRUE(config.ok());
  double a = 2.5;
  std::string b = "kept";
  int x = 0;
  config->Read("a", &a).Read("b", &b);
  config->Child("box");
  config->Items("list");
  for (ConfigReader& item : config->Items("items")) item.Read("x", &x);
  EXPECT_TRUE(config->Finish().ok()) << config->Finish();
  EXPECT_EQ(a, 2.5);
  EXPECT_EQ(b, "kept");
  EXPECT_EQ(x, 1);

  auto world = ConfigReader::FromString(yaml, {.name = "world", .null_is_absent = false});
  ASSERT_TRUE(world.ok());
  int size = 0;
  world->Read("a", &a).Require("b", &b);
  // A section without a value is one error, not one per key it lacks.
  world->RequireChild("box").Require("size", &size);
  world->Items("list");
  for (ConfigReader& item : world->Items("items")) item.Read("x", &x);
  EXPECT_EQ(world->Finish().message(),
            "world: a: has no value; b: has no value; box: has no value; list: has no value; "
            "items[0]: must be a mapping");
  EXPECT_EQ(a, 2.5);
  EXPECT_EQ(b, "kept");
}

TEST(ConfigReaderTest, OneErrorPerKey) {
  auto reader = ConfigReader::FromString("a: x\nb: -1\nsection: 5\n");
  ASSERT_TRUE(reader.ok());
  double a = 1;
  double b = 1;
  double inner = -1;
  reader->Read("a", &a).Read("b", &b);
  reader->Check(a > 0 && a < 0.5, "a", "must be in (0, 0.5)");  // a kept its default 1
  reader->Check(b > 0, "b", "must be > 0");
  ConfigReader section = reader->Child("section");
  section.Read("inner", &inner);
  section.Check(inner > 0, "inner", "must be > 0");  // the section itself is the error
  EXPECT_EQ(reader->Finish().message(),
            "config: a: has the wrong type or value 'x'; b: must be > 0; section: must be a "
            "mapping");
}

TEST(ConfigReaderTest, ErrorCarriesTheFirstPathAsItsField) {
  auto reader = ConfigReader::FromString("mapping: {resolution_m: fast}\nbogus: 1\n");
  ASSERT_TRUE(reader.ok());
  double resolution = 0.05;
  reader->Child("mapping").Read("resolution_m", &resolution);
  const absl::Status status = reader->Finish();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(status), "mapping.resolution_m");
  EXPECT_THAT(status.message(), HasSubstr("bogus: unknown key"));
  // The document's name leads syntax errors as well.
  const auto broken = ConfigReader::FromString("a: [1", {.name = "world"});
  EXPECT_EQ(broken.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(broken.status().message(), HasSubstr("world: yaml-cpp: error at line"));
}

}  // namespace
}  // namespace semnav
