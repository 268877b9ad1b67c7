#include "services/common/lexicon/canonical_term.h"

#include <gtest/gtest.h>

namespace semnav {
namespace {

TEST(CanonicalTermTest, NormalizesCaseArticlesPluralsAndSynonyms) {
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

TEST(CanonicalTermTest, ChineseNamesMapInsideLongerText) {
  EXPECT_EQ(CanonicalTerm("沙发"), "couch");
  EXPECT_EQ(CanonicalTerm("红色沙发"), "红色 couch");
  EXPECT_EQ(CanonicalTerm("笔记本电脑"), "laptop");  // not "笔记本" + "电脑"
  EXPECT_EQ(CanonicalTerm("卫生间"), "bathroom");
}

}  // namespace
}  // namespace semnav
