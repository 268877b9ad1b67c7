#include "services/reasoning/core/correction.h"

#include "gtest/gtest.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

class GatewayCorrectionTest : public ::testing::Test {
 protected:
  GatewayCorrectionTest() : parser_(&ShippedLexicon(), *TextSegmenter::Create()) {
    active_.name = "cup";
    active_.text = "杯子";
  }
  InstructionParser parser_;
  TargetSpec active_;
};

TEST_F(GatewayCorrectionTest, ChineseNotThisOneTheRedOne) {
  std::optional<Correction> correction =
      ReadCorrection(parser_.Parse("不是这个，是那个红色的"), active_);
  ASSERT_TRUE(correction.has_value());
  EXPECT_TRUE(correction->exclude_current);
  EXPECT_EQ(correction->target.name, "cup");
  EXPECT_EQ(correction->target.colours, std::vector<std::string>{"red"});
}

TEST_F(GatewayCorrectionTest, EnglishNotThatOneTheRedOne) {
  std::optional<Correction> correction =
      ReadCorrection(parser_.Parse("not that one, the red one"), active_);
  ASSERT_TRUE(correction.has_value());
  EXPECT_TRUE(correction->exclude_current);
  EXPECT_EQ(correction->target.colours, std::vector<std::string>{"red"});
}

TEST_F(GatewayCorrectionTest, NamingAnotherObjectReplacesTheTarget) {
  std::optional<Correction> correction =
      ReadCorrection(parser_.Parse("不对，是那个蓝色的瓶子"), active_);
  ASSERT_TRUE(correction.has_value());
  EXPECT_EQ(correction->target.name, "bottle");
  EXPECT_EQ(correction->target.colours, std::vector<std::string>{"blue"});
}

TEST_F(GatewayCorrectionTest, ANewInstructionIsNotACorrection) {
  EXPECT_FALSE(ReadCorrection(parser_.Parse("去厨房找红色杯子"), active_).has_value());
  EXPECT_FALSE(ReadCorrection(parser_.Parse("go to the door"), active_).has_value());
}

}  // namespace
}  // namespace semnav::reasoning
