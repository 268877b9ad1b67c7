#pragma once

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace semnav::planning::bench {

// Milliseconds taken by fn().
template <typename Fn>
double TimeMs(Fn&& fn) {
  const auto t0 = std::chrono::steady_clock::now();
  fn();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// This thread's CPU milliseconds taken by fn(): on the shared dev machine
// wall time grows with the load, CPU time does not.
template <typename Fn>
double CpuMs(Fn&& fn) {
  timespec t0;
  timespec t1;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t0);
  fn();
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t1);
  return (t1.tv_sec - t0.tv_sec) * 1e3 + (t1.tv_nsec - t0.tv_nsec) * 1e-6;
}

// The q-quantile (0..1) of samples, nearest rank; 0 when empty.
inline double Quantile(std::vector<double> samples, double q) {
  if (samples.empty()) return 0.0;
  const size_t k = std::min(samples.size() - 1, static_cast<size_t>(q * samples.size()));
  std::nth_element(samples.begin(), samples.begin() + k, samples.end());
  return samples[k];
}

}  // namespace semnav::planning::bench
