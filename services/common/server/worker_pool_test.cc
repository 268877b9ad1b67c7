#include "services/common/server/worker_pool.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
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

TEST(WorkerPoolTest, ANiceIncrementLowersOnlyThePoolsThreads) {
  const int caller = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
  std::atomic<int> in_pool{-100};
  std::atomic<int> in_plain_pool{-100};
  {
    WorkerPool background(1, 5);
    WorkerPool plain(1);
    ASSERT_TRUE(background.Submit(
        [&] { in_pool = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid())); }));
    ASSERT_TRUE(plain.Submit(
        [&] { in_plain_pool = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid())); }));
  }
  EXPECT_EQ(in_pool.load(), std::min(19, caller + 5));
  EXPECT_EQ(in_plain_pool.load(), caller);
  EXPECT_EQ(getpriority(PRIO_PROCESS, static_cast<id_t>(gettid())), caller);
}

}  // namespace
}  // namespace semnav
