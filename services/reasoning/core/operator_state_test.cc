#include "absl/strings/str_cat.h"
#include "gtest/gtest.h"
#include "services/reasoning/core/event_log.h"
#include "services/reasoning/core/lease_table.h"

namespace semnav::reasoning {
namespace {

const absl::Time kT0 = absl::FromUnixSeconds(1000);

TEST(GatewayLeaseTableTest, ExclusiveUntilExpiry) {
  LeaseTable leases;
  absl::StatusOr<LeaseInfo> alice = leases.Acquire("r1", "alice", absl::Seconds(30), kT0);
  ASSERT_TRUE(alice.ok());
  EXPECT_EQ(leases.Acquire("r1", "bob", absl::Seconds(30), kT0 + absl::Seconds(10)).status().code(),
            absl::StatusCode::kFailedPrecondition);
  EXPECT_TRUE(leases.CheckControl("r1", alice->lease_id, kT0).ok());
  EXPECT_EQ(leases.CheckControl("r1", "", kT0).code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_TRUE(leases.CheckControl("r2", "", kT0).ok());  // unleased robot
  // Re-acquire by the holder keeps the id; renew extends; expiry frees the robot.
  EXPECT_EQ(leases.Acquire("r1", "alice", absl::Seconds(5), kT0 + absl::Seconds(1))->lease_id,
            alice->lease_id);
  EXPECT_EQ(leases.Renew(alice->lease_id, absl::Seconds(20), kT0 + absl::Seconds(2))->expires_at,
            kT0 + absl::Seconds(22));
  EXPECT_TRUE(leases.CheckControl("r1", "", kT0 + absl::Seconds(22)).ok());
  EXPECT_EQ(
      leases.Renew(alice->lease_id, absl::Seconds(20), kT0 + absl::Seconds(23)).status().code(),
      absl::StatusCode::kNotFound);
  absl::StatusOr<LeaseInfo> bob =
      leases.Acquire("r1", "bob", absl::Seconds(30), kT0 + absl::Seconds(23));
  ASSERT_TRUE(bob.ok());
  EXPECT_NE(bob->lease_id, alice->lease_id);
  leases.Release(bob->lease_id);
  EXPECT_FALSE(leases.Current("r1", kT0 + absl::Seconds(24)).has_value());
}

TEST(GatewayEventLogTest, ReplayAfterIdAndTruncation) {
  EventLog log(3);
  for (int i = 0; i < 5; ++i)
    log.Append(1, i % 2 == 0 ? "r1" : "r2", "", absl::StrCat("e", i + 1), kT0);
  bool truncated = false;
  std::vector<LoggedEvent> all = log.After(0, "", "", &truncated);
  EXPECT_TRUE(truncated);  // ids 1 and 2 were dropped
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all.front().id, 3u);
  std::vector<LoggedEvent> r1 = log.After(2, "r1", "", &truncated);
  EXPECT_FALSE(truncated);
  ASSERT_EQ(r1.size(), 2u);
  EXPECT_EQ(r1[1].message, "e5");
  EXPECT_TRUE(log.After(5, "", "", &truncated).empty());
  EXPECT_EQ(log.last_id(), 5u);
}

TEST(GatewayEventLogTest, OneTasksEventsFromTheFirst) {
  EventLog log(10);
  log.Append(1, "r1", "task-1", "created", kT0);
  log.Append(6, "r2", "", "session opened", kT0);
  log.Append(2, "r1", "task-1", "succeeded", kT0);
  log.Append(1, "r1", "task-2", "created", kT0);
  bool truncated = true;
  std::vector<LoggedEvent> task1 = log.After(0, "", "task-1", &truncated);
  EXPECT_FALSE(truncated);
  ASSERT_EQ(task1.size(), 2u);
  EXPECT_EQ(task1[0].id, 1u);  // after id 0 includes event 1
  EXPECT_EQ(task1[1].message, "succeeded");
  EXPECT_TRUE(log.After(0, "r2", "task-1", &truncated).empty());
  ASSERT_EQ(log.After(1, "r1", "task-1", &truncated).size(), 1u);
}

}  // namespace
}  // namespace semnav::reasoning
