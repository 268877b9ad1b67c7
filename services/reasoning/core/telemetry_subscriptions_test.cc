// Telemetry subscriptions: a subscriber gets a sample of its own robot once per interval.
#include "services/reasoning/core/telemetry_subscriptions.h"

#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

TEST(TelemetrySubscriptionsTest, EachSubscriberIsDueOncePerIntervalForItsOwnRobot) {
  TelemetrySubscriptions<int> subscriptions;
  const absl::Time t0 = absl::FromUnixSeconds(1000);
  subscriptions.Add(1, "r1", absl::Milliseconds(100));  // 10 Hz
  subscriptions.Add(2, "r1", absl::Seconds(1));
  subscriptions.Add(3, "r2", absl::Milliseconds(100));

  EXPECT_EQ(subscriptions.TakeDue("r1", t0), (std::vector<int>{1, 2}));  // first sample at once
  EXPECT_TRUE(subscriptions.TakeDue("r1", t0 + absl::Milliseconds(99)).empty());
  EXPECT_EQ(subscriptions.TakeDue("r1", t0 + absl::Milliseconds(100)), (std::vector<int>{1}));
  EXPECT_EQ(subscriptions.TakeDue("r1", t0 + absl::Seconds(1)), (std::vector<int>{1, 2}));

  // All robots at once (the slow-telemetry ticker): r2's subscriber was never sent to.
  const auto due = subscriptions.TakeDue(t0 + absl::Milliseconds(1050));
  ASSERT_EQ(due.size(), 1u);
  EXPECT_EQ(due[0], std::make_pair(3, std::string("r2")));

  subscriptions.Remove(1);
  subscriptions.Add(2, "r2", absl::Milliseconds(100));  // replaces its r1 subscription
  EXPECT_TRUE(subscriptions.TakeDue("r1", t0 + absl::Seconds(5)).empty());
  EXPECT_EQ(subscriptions.TakeAll(), (std::vector<int>{2, 3}));
  EXPECT_TRUE(subscriptions.TakeAll().empty());
}

}  // namespace
}  // namespace semnav::reasoning
