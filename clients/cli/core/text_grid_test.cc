#include "clients/cli/core/text_grid.h"

#include "gtest/gtest.h"

namespace semnav::cli {
namespace {

TEST(TextGridTest, PlainRowsMapToHierarchicalValues) {
  absl::StatusOr<TextGrid> grid = ParseTextGrid("..3#\n?G@.\n");
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_EQ(grid->width, 4);
  EXPECT_EQ(grid->height, 2);
  EXPECT_EQ(grid->cells, (std::vector<uint8_t>{0, 0, 3, 100, 255, 0, 100, 0}));
}

TEST(TextGridTest, MovingAiHeaderIsSkippedAndChecked) {
  absl::StatusOr<TextGrid> grid =
      ParseTextGrid("type octile\nheight 2\nwidth 3\nmap\n.T.\r\nS.W\n");
  ASSERT_TRUE(grid.ok()) << grid.status();
  EXPECT_EQ(grid->cells, (std::vector<uint8_t>{0, 100, 0, 0, 0, 100}));
  EXPECT_EQ(ParseTextGrid("type octile\nheight 3\nwidth 3\nmap\n...\n").status().message(),
            "header says 3x3, rows are 3x1");
}

TEST(TextGridTest, RaggedRowsAndUnknownCharactersAreRejected) {
  EXPECT_EQ(ParseTextGrid("...\n..\n").status().message(), "row 1 has 2 cells, row 0 has 3");
  EXPECT_EQ(ParseTextGrid("..x\n").status().message(),
            "row 0 column 2: unknown cell character 'x'");
  EXPECT_FALSE(ParseTextGrid("\n\n").ok());
}

}  // namespace
}  // namespace semnav::cli
