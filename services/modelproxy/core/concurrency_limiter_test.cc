#include "services/modelproxy/core/concurrency_limiter.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

TEST(ModelProxyConcurrencyLimiterTest, WaitsUntilDeadlineWhenFullAndFreesOnRelease) {
  ConcurrencyLimiter limiter(2);
  auto a = limiter.Acquire(absl::Now() + absl::Seconds(1));
  std::optional<ConcurrencyLimiter::Permit> b = limiter.Acquire(absl::Now() + absl::Seconds(1));
  ASSERT_TRUE(a && b);
  EXPECT_EQ(limiter.in_flight(), 2);
  const absl::Time start = absl::Now();
  EXPECT_FALSE(limiter.Acquire(start + absl::Milliseconds(30)));
  EXPECT_GE(absl::Now() - start, absl::Milliseconds(30));
  b.reset();
  EXPECT_EQ(limiter.in_flight(), 1);
  EXPECT_TRUE(limiter.Acquire(absl::Now() + absl::Milliseconds(30)));
  EXPECT_EQ(limiter.in_flight(), 1);  // the temporary permit was released again
}

}  // namespace
}  // namespace semnav::modelproxy
