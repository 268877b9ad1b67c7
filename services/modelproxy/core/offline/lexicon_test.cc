#include "services/modelproxy/core/offline/lexicon.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy::offline {
namespace {

TEST(ModelProxyLexiconTest, CanonicalTermNormalizesCaseArticlesPluralsAndSynonyms) {
  EXPECT_EQ(CanonicalTerm("Sofas"), "couch");
  EXPECT_EQ(CanonicalTerm("the Living_Room"), "living room");
  EXPECT_EQ(CanonicalTerm("livingroom"), "living room");
  EXPECT_EQ(CanonicalTerm("knives"), "knife");
  EXPECT_EQ(CanonicalTerm("shelves"), "shelf");
  EXPECT_EQ(CanonicalTerm("Mobile phones"), "cell phone");
  EXPECT_EQ(CanonicalTerm("a red mug"), "red cup");
  EXPECT_EQ(CanonicalTerm("glass"), "glass");  // -ss is not a plural
  EXPECT_EQ(CanonicalTerm("bus"), "bus");      // too short to strip
  EXPECT_EQ(CanonicalTerm("coffee table"), "coffee table");
  EXPECT_EQ(CanonicalTerm("table"), "dining table");
}

TEST(ModelProxyLexiconTest, ChineseNamesMapInsideLongerText) {
  EXPECT_EQ(CanonicalTerm("沙发"), "couch");
  EXPECT_EQ(CanonicalTerm("红色沙发"), "红色 couch");
  EXPECT_EQ(CanonicalTerm("笔记本电脑"), "laptop");  // not "笔记本" + book
  EXPECT_EQ(CanonicalTerm("卫生间"), "bathroom");
}

TEST(ModelProxyLexiconTest, LexicalMatchScores) {
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
