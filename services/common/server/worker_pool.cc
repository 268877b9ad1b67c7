#include "services/common/server/worker_pool.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

namespace semnav {
namespace {

void LowerThisThreadsPriority(int nice_increment) {
  if (nice_increment <= 0) return;
  const pid_t thread = gettid();
  const int current = getpriority(PRIO_PROCESS, static_cast<id_t>(thread));
  // Raising nice needs no privilege; a failure leaves the thread at its priority.
  (void)setpriority(PRIO_PROCESS, static_cast<id_t>(thread),
                    std::min(19, current + nice_increment));
}

}  // namespace

WorkerPool::WorkerPool(int threads, int nice_increment) {
  for (int i = 0; i < threads; ++i) {
    threads_.emplace_back([this, nice_increment] {
      LowerThisThreadsPriority(nice_increment);
      Run();
    });
  }
}

WorkerPool::~WorkerPool() { Shutdown(); }

bool WorkerPool::Submit(std::function<void()> job) {
  absl::MutexLock lock(&mu_);
  if (stopping_) return false;
  jobs_.push_back(std::move(job));
  return true;
}

void WorkerPool::Shutdown() {
  {
    absl::MutexLock lock(&mu_);
    if (stopping_ && threads_.empty()) return;
    stopping_ = true;
  }
  for (std::thread& t : threads_) t.join();
  threads_.clear();
}

void WorkerPool::Run() {
  while (true) {
    std::function<void()> job;
    {
      absl::MutexLock lock(&mu_);
      mu_.Await(absl::Condition(
          +[](WorkerPool* p)
               ABSL_EXCLUSIVE_LOCKS_REQUIRED(p->mu_) { return p->stopping_ || !p->jobs_.empty(); },
          this));
      if (jobs_.empty()) return;  // stopping and drained
      job = std::move(jobs_.front());
      jobs_.pop_front();
    }
    job();
  }
}

}  // namespace semnav
