#include "services/common/cli/flags.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace semnav {
namespace {

const std::vector<FlagSpec> kSpecs = {
    {"config", "FILE", "YAML config"}, {"help", "", "show help"}, {"listen", "ADDR", "address"}};

absl::StatusOr<ParsedFlags> Parse(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  return ParseFlags(static_cast<int>(argv.size()), argv.data(), 1, kSpecs);
}

TEST(FlagsTest, ParsesValuesSwitchesAndPositionals) {
  auto parsed = Parse({"bin", "up", "--config", "a.yaml", "--listen=:1", "--help"});
  ASSERT_TRUE(parsed.ok());
  EXPECT_EQ(parsed->positional, std::vector<std::string>{"up"});
  EXPECT_EQ(*parsed->Get("config"), "a.yaml");
  EXPECT_EQ(*parsed->Get("listen"), ":1");
  EXPECT_TRUE(parsed->Has("help"));
  EXPECT_FALSE(parsed->Get("nope").has_value());
}

TEST(FlagsTest, UnknownAndIncompleteFlagsAreNamed) {
  EXPECT_EQ(Parse({"bin", "--colour"}).status().message(), "unknown flag --colour (see --help)");
  EXPECT_EQ(Parse({"bin", "--config"}).status().message(), "flag --config needs a value FILE");
  EXPECT_EQ(Parse({"bin", "--help=1"}).status().message(), "flag --help takes no value");
}

TEST(FlagsTest, HelpListsEveryFlag) {
  const std::string help = FlagsHelp(kSpecs);
  EXPECT_NE(help.find("--config FILE"), std::string::npos);
  EXPECT_NE(help.find("show help"), std::string::npos);
}

// Each program's main() calls ParseFlagsOrExit first, so these run it in a child process.
void ParseOrExit(std::vector<std::string> args) {
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  ParseFlagsOrExit(static_cast<int>(argv.size()), argv.data(), kSpecs, "bin",
                   "usage: bin [flags]\n");
  std::exit(7);  // parsed: main() carries on
}

TEST(FlagsDeathTest, UnknownFlagsMissingValuesAndArgumentsExitTwoWithUsage) {
  EXPECT_EXIT(ParseOrExit({"bin", "--colour"}), testing::ExitedWithCode(2),
              "bin: unknown flag --colour .*\nusage: bin \\[flags\\]");
  EXPECT_EXIT(ParseOrExit({"bin", "--listen"}), testing::ExitedWithCode(2),
              "bin: flag --listen needs a value ADDR\nusage: bin");
  EXPECT_EXIT(ParseOrExit({"bin", "stray"}), testing::ExitedWithCode(2),
              "bin: unexpected argument 'stray'\nusage: bin");
}

TEST(FlagsDeathTest, HelpExitsZeroAndKnownFlagsReturn) {
  EXPECT_EXIT(ParseOrExit({"bin", "--help"}), testing::ExitedWithCode(0), "");
  EXPECT_EXIT(ParseOrExit({"bin", "--listen", ":1", "-h"}), testing::ExitedWithCode(0), "");
  EXPECT_EXIT(ParseOrExit({"bin", "--listen", ":1", "--config=a.yaml"}), testing::ExitedWithCode(7),
              "");
}

}  // namespace
}  // namespace semnav
