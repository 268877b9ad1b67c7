#include "clients/cli/core/exit_codes.h"

#include <algorithm>

#include "gtest/gtest.h"

namespace semnav::cli {
namespace {

TEST(ExitCodesTest, EachStatusCodeMapsToItsDocumentedExitCode) {
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kOk)), 0);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kUnavailable)), 3);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kDeadlineExceeded)), 4);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kNotFound)), 5);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kInvalidArgument)), 6);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kOutOfRange)), 6);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kFailedPrecondition)), 7);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kAborted)), 7);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kAlreadyExists)), 7);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kUnauthenticated)), 8);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kPermissionDenied)), 8);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kResourceExhausted)), 9);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kInternal)), 1);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kDataLoss)), 1);
  EXPECT_EQ(ToInt(ExitCodeFor(absl::StatusCode::kUnimplemented)), 1);
}

TEST(ExitCodesTest, HelpListsEveryCodeOnce) {
  const std::string help = ExitCodeHelp();
  for (const char* line :
       {"   0  ok", "   2  usage error", "   3  service unreachable", "   5  not found",
        "  10  the followed task ended FAILED", "  11  the followed task ended CANCELLED"}) {
    EXPECT_NE(help.find(line), std::string::npos) << line << "\n" << help;
  }
  EXPECT_EQ(std::count(help.begin(), help.end(), '\n'), 12);
}

}  // namespace
}  // namespace semnav::cli
