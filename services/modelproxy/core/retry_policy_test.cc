#include "services/modelproxy/core/retry_policy.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

TEST(ModelProxyRetryPolicyTest, BackoffDoublesUpToTheCap) {
  RetryPolicy p;  // 200 ms, x2, cap 2 s, jitter 0.5
  EXPECT_EQ(p.Backoff(0, 0.0), absl::Milliseconds(200));
  EXPECT_EQ(p.Backoff(1, 0.0), absl::Milliseconds(400));
  EXPECT_EQ(p.Backoff(3, 0.0), absl::Milliseconds(1600));
  EXPECT_EQ(p.Backoff(4, 0.0), absl::Seconds(2));  // 3.2 s capped
}

TEST(ModelProxyRetryPolicyTest, JitterShrinksTheDelayProportionally) {
  RetryPolicy p;
  // 400 ms * (1 - 0.5 * 0.5) = 300 ms
  EXPECT_NEAR(absl::ToDoubleMilliseconds(p.Backoff(1, 0.5)), 300.0, 1e-6);
  p.jitter = 1.0;  // full jitter: u close to 1 gives almost no wait
  EXPECT_NEAR(absl::ToDoubleMilliseconds(p.Backoff(0, 0.99)), 2.0, 1e-6);
}

TEST(ModelProxyRetryPolicyTest, OnlyTransientCodesAreRetryable) {
  EXPECT_TRUE(IsRetryable(absl::ResourceExhaustedError("429")));
  EXPECT_TRUE(IsRetryable(absl::UnavailableError("503")));
  EXPECT_TRUE(IsRetryable(absl::DeadlineExceededError("timeout")));
  EXPECT_FALSE(IsRetryable(absl::DataLossError("malformed")));
  EXPECT_FALSE(IsRetryable(absl::InvalidArgumentError("400")));
  EXPECT_FALSE(IsRetryable(absl::UnauthenticatedError("401")));
  EXPECT_FALSE(IsRetryable(MarkNotRetryable(absl::UnavailableError("connection refused"))));
}

}  // namespace
}  // namespace semnav::modelproxy
