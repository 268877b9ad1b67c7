#include "services/common/lexicon/canonical_term.h"

#include <gtest/gtest.h>

#include "services/common/lexicon/lexicon.h"

namespace semnav {
namespace {

TEST(CanonicalTermTest, IsAsciiIsFalseForAnyByteAbove127) {
  EXPECT_TRUE(IsAscii("red mug"));
  EXPECT_TRUE(IsAscii(""));
  EXPECT_FALSE(IsAscii("汽车"));
  EXPECT_FALSE(IsAscii("caf\xC3\xA9"));  // "café": one non-ASCII letter is enough
}

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
  EXPECT_EQ(CanonicalTerm("bedside tables"), "bedside table");
  EXPECT_EQ(CanonicalTerm("table"), "dining table");
  EXPECT_EQ(CanonicalTerm("cellar"), "basement");
}

TEST(CanonicalTermTest, ChineseNamesMapInsideLongerText) {
  EXPECT_EQ(CanonicalTerm("沙发"), "couch");
  EXPECT_EQ(CanonicalTerm("红色沙发"), "红色 couch");
  EXPECT_EQ(CanonicalTerm("笔记本电脑"), "laptop");  // not "笔记本" + "电脑"
  EXPECT_EQ(CanonicalTerm("卫生间"), "bathroom");
  EXPECT_EQ(CanonicalTerm("车库"), "garage");    // not "车" (car) + "库"
  EXPECT_EQ(CanonicalTerm("书包"), "backpack");  // not "书" (book) + "包" (handbag)
}

// The synonyms are the lexicon's: forms that were only in lexicon.tsv before the model proxy's
// own list was folded into it.
TEST(CanonicalTermTest, TakesTheSynonymsOfTheLexicon) {
  EXPECT_EQ(CanonicalTerm("cupboards"), "cabinet");
  EXPECT_EQ(CanonicalTerm("Hallway"), "corridor");
  EXPECT_EQ(CanonicalTerm("bookshelf"), "shelf");
  EXPECT_EQ(CanonicalTerm("书架"), "shelf");
  EXPECT_EQ(CanonicalTerm("rucksack"), "backpack");
  EXPECT_EQ(CanonicalTerm("bins"), "trash can");
  // Only objects and rooms: instruction words and colours stay as they are.
  EXPECT_EQ(CanonicalTerm("go"), "go");
  EXPECT_EQ(CanonicalTerm("红色"), "红色");
}

TEST(CanonicalTermTest, EveryObjectAndRoomFormNamesItsEntry) {
  int forms = 0;
  for (const LexiconEntry& entry : Lexicon::Embedded().entries()) {
    if (entry.kind != TermKind::kObject && entry.kind != TermKind::kRoom) continue;
    const std::string canonical = CanonicalTerm(entry.canonical);
    for (const auto* list : {&entry.english, &entry.chinese}) {
      for (const std::string& form : *list) {
        EXPECT_EQ(CanonicalTerm(form), canonical) << form;
        ++forms;
      }
    }
  }
  EXPECT_GT(forms, 300);
}

}  // namespace
}  // namespace semnav
