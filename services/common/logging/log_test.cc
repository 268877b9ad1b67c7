#include "services/common/logging/log.h"

#include <gtest/gtest.h>

namespace semnav {
namespace {

TEST(LogTest, FormatsLogfmtWithQuotingOnlyWhenNeeded) {
  SetLogComponent("semnav-test");
  EXPECT_EQ(
      FormatLogLine(LogLevel::kInfo, "frame_rejected",
                    {{"robot", "r1"}, {"reason", "depth \"size\" wrong"}, {"n", 3}, {"ok", false}}),
      "level=info svc=semnav-test event=frame_rejected robot=r1 "
      "reason=\"depth \\\"size\\\" wrong\" n=3 ok=false");
  EXPECT_EQ(FormatLogLine(LogLevel::kError, "x", {{"empty", ""}}),
            "level=error svc=semnav-test event=x empty=\"\"");
}

TEST(LogTest, ParsesLevelsAndRejectsOthersNamingTheFlag) {
  EXPECT_EQ(*ParseLogLevel("INFO"), LogLevel::kInfo);
  EXPECT_EQ(*ParseLogLevel("warn"), LogLevel::kWarning);
  absl::StatusOr<LogLevel> bad = ParseLogLevel("loud");
  EXPECT_EQ(bad.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(bad.status().message().find("log_level"), absl::string_view::npos);
}

TEST(LogTest, QuietByDefault) { EXPECT_EQ(GetLogLevel(), LogLevel::kWarning); }

}  // namespace
}  // namespace semnav
