#include "services/common/lexicon/lexicon.h"

#include <fstream>
#include <sstream>
#include <string>

#include "absl/strings/match.h"
#include "gtest/gtest.h"
#include "services/common/lexicon/embedded_lexicon.h"

namespace semnav {
namespace {

const Lexicon& ShippedLexicon() {
  static const Lexicon* const lexicon = [] {
    absl::StatusOr<Lexicon> loaded = Lexicon::Load(Lexicon::DefaultPath());
    EXPECT_TRUE(loaded.ok()) << loaded.status();
    return new Lexicon(loaded.ok() ? *std::move(loaded) : Lexicon());
  }();
  return *lexicon;
}

TEST(LexiconTest, CoversAllCoco80ClassesInBothLanguages) {
  std::ifstream classes(std::string(SEMNAV_SHARED_DATA_DIR) +
                        "/object-priors/conceptnet_atlocation_coco80/ms-coco-80-categories.txt");
  ASSERT_TRUE(classes.good());
  int count = 0;
  for (std::string name; std::getline(classes, name);) {
    if (name.empty()) continue;
    ++count;
    const LexiconEntry* entry = ShippedLexicon().Find(name, TermKind::kObject);
    ASSERT_NE(entry, nullptr) << name;
    EXPECT_EQ(entry->canonical, name);
    EXPECT_FALSE(entry->chinese.empty()) << name;
  }
  EXPECT_EQ(count, 80);
}

// Every object and room can be asked for in Chinese (the simulator's benchmark names its targets
// by the first Chinese form: clients/sim/bench/target_names.h).
TEST(LexiconTest, EveryObjectAndRoomHasAChineseName) {
  int objects = 0;
  for (const LexiconEntry& entry : ShippedLexicon().entries()) {
    if (entry.kind != TermKind::kObject && entry.kind != TermKind::kRoom) continue;
    objects += entry.kind == TermKind::kObject ? 1 : 0;
    EXPECT_FALSE(entry.chinese.empty()) << entry.canonical;
    EXPECT_FALSE(entry.english.empty()) << entry.canonical;
  }
  EXPECT_GE(objects, 80);
}

TEST(LexiconTest, SynonymsAndChineseMapToTheCanonicalName) {
  const Lexicon& lexicon = ShippedLexicon();
  EXPECT_EQ(lexicon.CanonicalObject("Sofa"), "couch");
  EXPECT_EQ(lexicon.CanonicalObject("沙发"), "couch");
  EXPECT_EQ(lexicon.CanonicalObject("fire_extinguisher"), "fire extinguisher");
  EXPECT_EQ(lexicon.CanonicalObject("灭火器"), "fire extinguisher");
  EXPECT_EQ(lexicon.CanonicalObject("厨房"), "kitchen");
  EXPECT_EQ(lexicon.CanonicalObject("桥"), "bridge");  // outdoor UAV scenes (seed 000's river)
  EXPECT_EQ(lexicon.CanonicalObject("flux capacitor"), "flux capacitor");
  ASSERT_NE(lexicon.Find("红色", TermKind::kColour), nullptr);
  EXPECT_EQ(lexicon.Find("红色", TermKind::kColour)->canonical, "red");
  EXPECT_EQ(lexicon.Find("左边", TermKind::kRelation)->canonical, "left_of");
  // "orange" is both a fruit and a colour; lookup returns both.
  EXPECT_EQ(lexicon.Lookup("orange").size(), 2u);
}

// The copy compiled into the binaries (CanonicalTerm's synonyms) is the data file, byte for byte.
TEST(LexiconTest, EmbeddedTextIsTheDataFile) {
  std::ifstream in(Lexicon::DefaultPath());
  ASSERT_TRUE(in.good()) << Lexicon::DefaultPath();
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(std::string(EmbeddedLexiconTsv()), text.str());
  EXPECT_EQ(Lexicon::Embedded().entries().size(), ShippedLexicon().entries().size());
  EXPECT_EQ(Lexicon::Embedded().CanonicalObject("沙发"), "couch");
}

// Entries merged from the model proxy's former synonym list (issue 17): the gateway reads them too.
TEST(LexiconTest, KnowsTheModelProxysFormerSynonyms) {
  const Lexicon& lexicon = ShippedLexicon();
  EXPECT_EQ(lexicon.CanonicalObject("settee"), "couch");
  EXPECT_EQ(lexicon.CanonicalObject("stove"), "oven");
  EXPECT_EQ(lexicon.CanonicalObject("wc"), "bathroom");
  EXPECT_EQ(lexicon.CanonicalObject("cellar"), "basement");
  EXPECT_EQ(lexicon.CanonicalObject("coffee table"), "coffee table");
  ASSERT_NE(lexicon.Find("茶几", TermKind::kObject), nullptr);
  EXPECT_EQ(lexicon.Find("茶几", TermKind::kObject)->canonical, "coffee table");
}

TEST(LexiconTest, RejectsMalformedLines) {
  EXPECT_EQ(Lexicon::Parse("object\tcup\tcup\n").status().code(),
            absl::StatusCode::kInvalidArgument);
  absl::StatusOr<Lexicon> bad_kind = Lexicon::Parse("gadget\tx\tx\tx\n");
  EXPECT_EQ(bad_kind.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_TRUE(absl::StrContains(bad_kind.status().message(), "line 1"));
}

}  // namespace
}  // namespace semnav
