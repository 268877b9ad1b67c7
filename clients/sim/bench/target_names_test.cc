#include "clients/sim/bench/target_names.h"

#include <gtest/gtest.h>

#include "clients/sim/core/label_lexicon.h"

namespace semnav::sim::bench {
namespace {

// Every label a world may use (any English form of a lexicon object) has a Chinese name: the
// lexicon's first Chinese form of that object.
TEST(SimBenchTargetNamesTest, EveryLexiconLabelHasItsChineseName) {
  const absl::StatusOr<const Lexicon*> lexicon = LabelLexicon();
  ASSERT_TRUE(lexicon.ok()) << lexicon.status();
  int labels = 0;
  for (const LexiconEntry& entry : (*lexicon)->entries()) {
    if (entry.kind != TermKind::kObject) continue;
    ASSERT_FALSE(entry.chinese.empty()) << entry.canonical;
    for (const std::string& form : entry.english) {
      ++labels;
      EXPECT_EQ(ChineseName(form), entry.chinese.front()) << form;
    }
  }
  EXPECT_GE(labels, 90);
}

TEST(SimBenchTargetNamesTest, NamesTheLabelsTheOldTableMissed) {
  EXPECT_EQ(ChineseName("bicycle"), "自行车");
  EXPECT_EQ(ChineseName("truck"), "卡车");
  EXPECT_EQ(ChineseName("bus"), "公交车");
  EXPECT_EQ(ChineseName("trash can"), "垃圾桶");
  EXPECT_EQ(ChineseName("umbrella"), "雨伞");
  EXPECT_EQ(ChineseName("table"), "餐桌");  // a form of "dining table"
  // The names the benchmark asked for before stay the same.
  EXPECT_EQ(ChineseName("clock"), "时钟");
  EXPECT_EQ(ChineseName("sink"), "水槽");
  EXPECT_EQ(ChineseName("potted plant"), "盆栽");
  EXPECT_FALSE(ChineseName("spaceship").has_value());
}

}  // namespace
}  // namespace semnav::sim::bench
