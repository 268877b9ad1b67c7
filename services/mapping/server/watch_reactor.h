#pragma once

#include <grpcpp/grpcpp.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <thread>

#include "absl/synchronization/mutex.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "services/mapping/core/mapping_engine.h"

namespace semnav::mapping {

// A server stream fed by its own thread: it waits for the map revision to move, asks `next` for
// a message, writes it, waits for the write, and sleeps `interval` (the rate limit). Ends when
// the client cancels or `stopping` is set (server shutdown: UNAVAILABLE, clients resume with
// since_revision).
template <typename Response>
class WatchReactor : public grpc::ServerWriteReactor<Response> {
 public:
  // next(last_sent_revision, first, out) fills `out` and returns the revision it reflects, or
  // nullopt when there is nothing new to send.
  using Producer = std::function<std::optional<uint64_t>(uint64_t, bool, Response*)>;

  WatchReactor(const MappingEngine& engine, const std::atomic<bool>& stopping,
               absl::Duration interval, uint64_t since_revision, Producer next)
      : engine_(engine),
        stopping_(stopping),
        interval_(interval),
        last_sent_(since_revision),
        next_(std::move(next)) {
    std::thread([this] { Run(); }).detach();
  }

  void OnWriteDone(bool ok) override {
    absl::MutexLock lock(&mu_);
    write_ok_ = ok;
    write_pending_ = false;
  }
  void OnCancel() override {
    absl::MutexLock lock(&mu_);
    cancelled_ = true;
  }
  void OnDone() override { delete this; }

 private:
  static constexpr absl::Duration kPoll = absl::Milliseconds(100);

  bool Cancelled() {
    absl::MutexLock lock(&mu_);
    return cancelled_;
  }
  bool Ending() { return stopping_.load() || Cancelled(); }

  bool WriteAndWait() {
    absl::MutexLock lock(&mu_);
    write_pending_ = true;
    this->StartWrite(&response_);
    mu_.Await(absl::Condition(
        +[](WatchReactor* r)
             ABSL_EXCLUSIVE_LOCKS_REQUIRED(r->mu_) { return !r->write_pending_ || r->cancelled_; },
        this));
    return !write_pending_ && write_ok_;
  }

  void Run() {
    uint64_t seen = 0;
    bool first = true;
    while (!Ending()) {
      if (!first) seen = engine_.AwaitChange(seen, kPoll);
      if (first) seen = engine_.revision();
      response_.Clear();
      const std::optional<uint64_t> revision = next_(last_sent_, first, &response_);
      first = false;
      if (!revision.has_value()) continue;
      if (!WriteAndWait()) break;
      last_sent_ = *revision;
      // Slices of at most kPoll / 4 (to notice cancellation) that end at `until`: an interval
      // below 25 ms is honoured, not rounded up to a whole slice.
      for (absl::Time until = absl::Now() + interval_; absl::Now() < until && !Ending();) {
        absl::SleepFor(std::min(kPoll / 4, until - absl::Now()));
      }
    }
    // Finish is the last touch of `this`: OnDone may delete it right after.
    this->Finish(stopping_.load() && !Cancelled()
                     ? grpc::Status(grpc::StatusCode::UNAVAILABLE, "server shutting down")
                     : grpc::Status::OK);
  }

  const MappingEngine& engine_;
  const std::atomic<bool>& stopping_;
  absl::Duration interval_;
  uint64_t last_sent_;
  Producer next_;
  Response response_;
  absl::Mutex mu_;
  bool write_pending_ ABSL_GUARDED_BY(mu_) = false;
  bool write_ok_ ABSL_GUARDED_BY(mu_) = true;
  bool cancelled_ ABSL_GUARDED_BY(mu_) = false;
};

}  // namespace semnav::mapping
