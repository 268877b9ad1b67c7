#include "services/relocalization/bench/evaluation.h"

#include <time.h>

#include <chrono>

namespace semnav::relocalization::bench {
namespace {

// Wall and thread-CPU stopwatch for one call.
class Stopwatch {
 public:
  Stopwatch() : wall_(std::chrono::steady_clock::now()), cpu_(ThreadCpuMs()) {}
  void Stop(eval::KeyframeOutcome& o) const {
    o.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_).count();
    o.cpu_ms = ThreadCpuMs() - cpu_;
  }

 private:
  static double ThreadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
  }
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

}  // namespace

Comparison RunComparison(const eval::Scenario& scenario, const RelocalizationParams& params,
                         const eval::BaselineParams& baseline, const eval::SuccessBounds& bounds) {
  const IndexedLandmarks map(scenario.map);
  std::vector<eval::KeyframeOutcome> ours, theirs;
  for (const eval::Keyframe& k : scenario.keyframes) {
    eval::KeyframeOutcome o;
    const Stopwatch ours_watch;
    const auto r = Relocalize(IndexedLandmarks(k.observed), map, params);
    ours_watch.Stop(o);
    o.answered = r.ok() && r->reliable;
    if (o.answered) o.error = eval::ComputePoseError(r->map_from_query, k.map_from_query);
    ours.push_back(o);

    eval::KeyframeOutcome ob;
    const Stopwatch baseline_watch;
    const auto b =
        eval::RelocalizeNearestDescriptorRansac(IndexedLandmarks(k.observed), map, baseline);
    baseline_watch.Stop(ob);
    ob.answered = b.ok();
    if (ob.answered) ob.error = eval::ComputePoseError(b->map_from_query, k.map_from_query);
    theirs.push_back(ob);
  }
  return {eval::Summarize(ours, bounds), eval::Summarize(theirs, bounds)};
}

}  // namespace semnav::relocalization::bench
