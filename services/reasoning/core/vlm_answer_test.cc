#include "services/reasoning/core/vlm_answer.h"

#include "absl/strings/match.h"
#include "gtest/gtest.h"
#include "services/reasoning/core/search_prompts.h"

namespace semnav::reasoning {
namespace {

TEST(GatewayVlmAnswerTest, SeedExampleAndVariants) {
  std::vector<CodeDescription> pairs = ParseCodeDescriptions(
      "Code:G5A, Description: 黄色共享单车旁地面区域\n"
      "code： f6a， description： 车库架上骑行头盔  \n"
      "I also see a tree.\n"
      "Code: 5GA, Description: malformed code is skipped");
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0].code, "G5A");
  EXPECT_EQ(pairs[0].description, "黄色共享单车旁地面区域");
  EXPECT_EQ(pairs[1].code, "F6A");
  EXPECT_EQ(pairs[1].description, "车库架上骑行头盔");
  EXPECT_TRUE(ParseCodeDescriptions("").empty());
}

TEST(GatewayVlmAnswerTest, ADescriptionNamesTheTargetOnlyWhenItSaysTheTargetIsThere) {
  // The simulated model's two forms: the target seen, or a passage beyond "no <target> here".
  EXPECT_TRUE(DescriptionNamesTarget("car seen here", "car"));
  EXPECT_FALSE(DescriptionNamesTarget("no car here; road leading to another area", "car"));
  EXPECT_FALSE(DescriptionNamesTarget("road leading to another area", "car"));
  // Free text of a real model: whole words, any case, adjectives dropped, negations anywhere
  // before the mention in its clause.
  EXPECT_TRUE(DescriptionNamesTarget("A red Car parked by the wall", "car"));
  EXPECT_TRUE(DescriptionNamesTarget("a mug on the kitchen shelf", "red mug"));
  EXPECT_FALSE(DescriptionNamesTarget("a carpet in the hall", "car"));
  EXPECT_FALSE(DescriptionNamesTarget("there is not a single car", "car"));
  EXPECT_FALSE(DescriptionNamesTarget("this isn't a car, it is a van", "car"));
  EXPECT_FALSE(DescriptionNamesTarget("road without cars", "car"));  // "cars" is another word
  // A clause of its own after a negated one: "sofa" reads as the lexicon's "couch".
  EXPECT_TRUE(DescriptionNamesTarget("No sofa in the hall, but a couch by the window", "sofa"));
  // Chinese: substrings, full-width clause marks, 没有 negates.
  EXPECT_TRUE(DescriptionNamesTarget("汽车停在楼旁", "汽车"));
  EXPECT_FALSE(DescriptionNamesTarget("这里没有汽车", "汽车"));
  EXPECT_TRUE(DescriptionNamesTarget("这里没有人，汽车停在路边", "汽车"));
  EXPECT_FALSE(DescriptionNamesTarget("", "car"));
  EXPECT_FALSE(DescriptionNamesTarget("car seen here", ""));
}

TEST(GatewaySearchPromptTest, ZeroShotReplacementKeepsTheLogic) {
  const std::string helmet = BuildSearchPrompt("bicycle helmet");
  const std::string umbrella = BuildSearchPrompt("umbrella");
  EXPECT_TRUE(absl::StrContains(helmet, "[bicycle helmet]"));
  EXPECT_FALSE(absl::StrContains(umbrella, "helmet"));
  for (const std::string* prompt : {&helmet, &umbrella}) {
    EXPECT_TRUE(absl::StrContains(*prompt, "Question A (recognition)"));
    EXPECT_TRUE(absl::StrContains(*prompt, "Question B (evaluation"));
    EXPECT_TRUE(absl::StrContains(*prompt, "Code: <code>, Description: <description>"));
  }
  // Replacing the target back yields the same text: only the target differs.
  std::string replaced = umbrella;
  for (std::size_t at; (at = replaced.find("umbrella")) != std::string::npos;) {
    replaced.replace(at, 8, "bicycle helmet");
  }
  EXPECT_EQ(replaced, helmet);
}

TEST(GatewaySearchPromptTest, RegionScoreParsing) {
  EXPECT_EQ(*ParseRegionScore("4"), 4);
  EXPECT_EQ(*ParseRegionScore("Score: -3 because..."), -3);
  EXPECT_EQ(ParseRegionScore("7").status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ParseRegionScore("likely").status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_TRUE(absl::StrContains(BuildRegionScorePrompt("helmet", {"bike rack", "road side"}),
                                "- bike rack\n"));
}

}  // namespace
}  // namespace semnav::reasoning
