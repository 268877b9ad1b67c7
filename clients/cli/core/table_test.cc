#include "clients/cli/core/table.h"

#include "gtest/gtest.h"

namespace semnav::cli {
namespace {

TEST(TableTest, PadsColumnsAndRightAlignsNumbers) {
  Table table({"ID", "LABEL", "X"});
  table.AddRow({"7", "chair", "1.50"});
  table.AddRow({"12", "fire extinguisher", "-10.25"});
  EXPECT_EQ(table.Render(),
            "ID  LABEL                   X\n"
            " 7  chair                1.50\n"
            "12  fire extinguisher  -10.25\n");
}

TEST(TableTest, WideCharactersCountTwoColumnsAndMissingCellsAreEmpty) {
  Table table({"LABEL", "ROOM", "N"});
  table.AddRow({"红色杯子", "kitchen", "3"});
  table.AddRow({"cup"});
  EXPECT_EQ(table.Render(),
            "LABEL     ROOM     N\n"
            "红色杯子  kitchen  3\n"
            "cup\n");
}

TEST(TableTest, HeaderOnlyWhenEmpty) {
  Table table({"MAP", "BYTES"});
  EXPECT_TRUE(table.empty());
  EXPECT_EQ(table.Render(), "MAP  BYTES\n");
}

TEST(TableTest, DisplayWidthAndNames) {
  EXPECT_EQ(DisplayWidth("abc"), 3u);
  EXPECT_EQ(DisplayWidth("厨房"), 4u);
  EXPECT_EQ(DisplayWidth("é"), 1u);
  EXPECT_EQ(ShortEnumName("TASK_STATUS_RUNNING", "TASK_STATUS_"), "RUNNING");
  EXPECT_EQ(ShortEnumName("OTHER", "TASK_STATUS_"), "OTHER");
  EXPECT_EQ(FormatFixed(1.23456, 2), "1.23");
  EXPECT_EQ(FormatFixed(-0.5, 0), "-0");
}

}  // namespace
}  // namespace semnav::cli
