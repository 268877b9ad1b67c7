#include "services/modelproxy/core/offline/lexical_match.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy::offline {
namespace {

TEST(ModelProxyLexicalMatchTest, LexicalMatchScores) {
  const LexicalScores s;
  EXPECT_DOUBLE_EQ(LexicalMatch("cup", "cup", s), 1.0);
  EXPECT_DOUBLE_EQ(LexicalMatch("red cup", "cup", s), 0.9);
  EXPECT_DOUBLE_EQ(LexicalMatch("cup", "coffee cup", s), 0.8);
  EXPECT_DOUBLE_EQ(LexicalMatch("red chair", "blue chair", s), 0.7 * 2.0 * 1.0 / 4.0);
  EXPECT_DOUBLE_EQ(LexicalMatch("chair", "toilet", s), 0.0);
  EXPECT_DOUBLE_EQ(LexicalMatch("", "toilet", s), 0.0);
  EXPECT_FALSE(ContainsPhrase("wine glass", "win"));  // whole words only
  EXPECT_TRUE(ContainsPhrase("big wine glass", "wine glass"));
}

}  // namespace
}  // namespace semnav::modelproxy::offline
