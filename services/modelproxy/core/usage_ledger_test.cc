#include "services/modelproxy/core/usage_ledger.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

TEST(ModelProxyUsageLedgerTest, TotalsPerCallerAndBackendWithFilters) {
  UsageLedger ledger;
  ledger.RecordAnswer({"r1", "t1"}, "openai", {100, 20}, false);
  ledger.RecordAnswer({"r1", "t1"}, "openai", {50, 5}, false);
  ledger.RecordAnswer({"r1", "t1"}, "openai", {50, 5}, /*cached=*/true);
  ledger.RecordAnswer({"r2", "t9"}, "offline", {0, 0}, false);
  ledger.RecordFailure({"r1", "t2"});

  const std::vector<UsageRow> r1 = ledger.Query("r1", "");
  ASSERT_EQ(r1.size(), 2u);
  EXPECT_EQ(r1[0].task_id, "t1");
  EXPECT_EQ(r1[0].backend, "openai");
  EXPECT_EQ(r1[0].totals.calls, 3);
  EXPECT_EQ(r1[0].totals.cached_calls, 1);
  EXPECT_EQ(r1[0].totals.input_tokens, 150);  // cache hits spend no tokens
  EXPECT_EQ(r1[0].totals.output_tokens, 25);
  EXPECT_EQ(r1[1].task_id, "t2");
  EXPECT_EQ(r1[1].backend, "");
  EXPECT_EQ(r1[1].totals.failed_calls, 1);
  EXPECT_EQ(ledger.Query("", "t9").size(), 1u);
  EXPECT_EQ(ledger.Query("", "").size(), 3u);
  EXPECT_TRUE(ledger.Query("r3", "").empty());
}

}  // namespace
}  // namespace semnav::modelproxy
