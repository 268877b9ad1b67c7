#include "clients/cli/core/progress_line.h"

#include <sstream>

#include "gtest/gtest.h"

namespace semnav::cli {
namespace {

TEST(ProgressLineTest, ShowsBarPercentStepPhaseAndReason) {
  TaskProgress progress{"task-3", "RUNNING",      0.4,         2,
                        5,        "FIND red cup", "exploring", "no match yet"};
  EXPECT_EQ(
      FormatProgressLine(progress, 10),
      "task-3  RUNNING    [####------]   40%  step 3/5 FIND red cup  exploring  -- no match yet");
}

TEST(ProgressLineTest, PendingWithoutStepsAndFinishedClampsTheStep) {
  EXPECT_EQ(FormatProgressLine({"task-1", "PENDING", 0.0, 0, 0, "", "", ""}, 4),
            "task-1  PENDING    [----]    0%");
  EXPECT_EQ(FormatProgressLine({"task-1", "SUCCEEDED", 1.0, 2, 2, "", "done", ""}, 4),
            "task-1  SUCCEEDED  [####]  100%  step 2/2  done");
}

TEST(ProgressLineTest, LivePrinterRewritesOneLineAndSkipsRepeats) {
  std::ostringstream out;
  ProgressPrinter printer(out, /*live=*/true);
  printer.Show("a");
  printer.Show("a");
  printer.Show("b");
  printer.Finish();
  EXPECT_EQ(out.str(), "\r\033[Ka\r\033[Kb\n");
}

TEST(ProgressLineTest, PipePrinterWritesEachChangeOnItsOwnLine) {
  std::ostringstream out;
  ProgressPrinter printer(out, /*live=*/false);
  printer.Show("a");
  printer.Show("a");
  printer.Show("b");
  printer.Finish();
  EXPECT_EQ(out.str(), "a\nb\n");
}

}  // namespace
}  // namespace semnav::cli
