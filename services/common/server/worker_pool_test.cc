#include "services/common/server/worker_pool.h"

#include <gtest/gtest.h>

#include <atomic>

namespace semnav {
namespace {

TEST(WorkerPoolTest, RunsQueuedJobsBeforeStoppingAndRefusesNewOnes) {
  std::atomic<int> done{0};
  WorkerPool pool(2);
  for (int i = 0; i < 50; ++i) {
    ASSERT_TRUE(pool.Submit([&done] {
      absl::SleepFor(absl::Milliseconds(1));
      ++done;
    }));
  }
  pool.Shutdown();
  EXPECT_EQ(done.load(), 50);
  EXPECT_FALSE(pool.Submit([&done] { ++done; }));
  EXPECT_EQ(done.load(), 50);
}

}  // namespace
}  // namespace semnav
