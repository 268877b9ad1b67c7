#pragma once
// Fixed threads running queued jobs, so long work (searches, model calls blocking on network
// I/O) never holds gRPC's callback threads.
#include <deque>
#include <functional>
#include <thread>
#include <vector>

#include "absl/synchronization/mutex.h"

namespace semnav {

class WorkerPool {
 public:
  // `nice_increment` > 0 lowers the threads' scheduling priority (Linux nice is per thread, and
  // threads they start inherit it): background work yields the CPU to latency-bound calls.
  explicit WorkerPool(int threads, int nice_increment = 0);
  ~WorkerPool();  // Shutdown()
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  // False (job not run) after Shutdown().
  bool Submit(std::function<void()> job);
  // Runs the jobs already queued, then joins the threads. Idempotent.
  void Shutdown();

 private:
  void Run();

  absl::Mutex mu_;
  std::deque<std::function<void()>> jobs_ ABSL_GUARDED_BY(mu_);
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  std::vector<std::thread> threads_;
};

}  // namespace semnav
