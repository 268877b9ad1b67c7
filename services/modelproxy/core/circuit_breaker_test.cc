#include "services/modelproxy/core/circuit_breaker.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

const absl::Time kT0 = absl::FromUnixSeconds(1000);

TEST(ModelProxyCircuitBreakerTest, OpensAfterThresholdAndProbesOnceWhenHalfOpen) {
  CircuitBreaker b({/*failure_threshold=*/2, /*open_duration=*/absl::Seconds(10)});
  EXPECT_TRUE(b.Allow(kT0));
  b.RecordFailure(kT0);
  EXPECT_EQ(b.state(kT0), BreakerState::kClosed);
  b.RecordFailure(kT0);
  EXPECT_EQ(b.state(kT0), BreakerState::kOpen);
  EXPECT_FALSE(b.Allow(kT0 + absl::Seconds(9)));
  EXPECT_EQ(b.state(kT0 + absl::Seconds(10)), BreakerState::kHalfOpen);
  EXPECT_TRUE(b.Allow(kT0 + absl::Seconds(10)));   // the probe
  EXPECT_FALSE(b.Allow(kT0 + absl::Seconds(10)));  // nobody else while it runs
  b.RecordFailure(kT0 + absl::Seconds(11));        // probe failed: open for another 10 s
  EXPECT_FALSE(b.Allow(kT0 + absl::Seconds(20)));
  EXPECT_TRUE(b.Allow(kT0 + absl::Seconds(21)));
  b.RecordSuccess();
  EXPECT_EQ(b.state(kT0 + absl::Seconds(21)), BreakerState::kClosed);
  EXPECT_EQ(b.consecutive_failures(), 0);
}

TEST(ModelProxyCircuitBreakerTest, SuccessResetsTheFailureCount) {
  CircuitBreaker b({3, absl::Seconds(10)});
  b.RecordFailure(kT0);
  b.RecordFailure(kT0);
  b.RecordSuccess();
  b.RecordFailure(kT0);
  EXPECT_EQ(b.consecutive_failures(), 1);
  EXPECT_EQ(b.state(kT0), BreakerState::kClosed);
}

}  // namespace
}  // namespace semnav::modelproxy
