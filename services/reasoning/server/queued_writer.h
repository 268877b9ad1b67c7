// Write side shared by the gateway's streaming reactors: messages are queued from any thread and
// written one at a time; Close finishes the call after the queue drains.
#pragma once

#include <grpcpp/support/status.h>

#include <deque>

#include "absl/synchronization/mutex.h"
#include "services/reasoning/server/stream_sink.h"

namespace semnav::reasoning {

// `Reactor` is grpc::ServerWriteReactor<Message> or grpc::ServerBidiReactor<In, Message>.
template <typename Reactor, typename Message>
class QueuedWriter : public Reactor, public StreamSink<Message> {
 public:
  void Send(const Message& message) override {
    absl::MutexLock lock(&write_mu_);
    if (closing_) return;
    queue_.push_back(message);
    if (!writing_) {
      writing_ = true;
      this->StartWrite(&queue_.front());
    }
  }

  void Close(const grpc::Status& status) override {
    absl::MutexLock lock(&write_mu_);
    if (closing_) return;
    closing_ = true;
    final_status_ = status;
    if (!writing_) FinishLocked();
  }

  void OnWriteDone(bool ok) override {
    absl::MutexLock lock(&write_mu_);
    queue_.pop_front();
    if (!ok) {
      // The client is gone; nothing more can be written.
      queue_.clear();
      closing_ = true;
    }
    if (!queue_.empty()) {
      this->StartWrite(&queue_.front());
      return;
    }
    writing_ = false;
    if (closing_) FinishLocked();
  }

  void OnCancel() override { Close(grpc::Status::CANCELLED); }

 private:
  void FinishLocked() ABSL_EXCLUSIVE_LOCKS_REQUIRED(write_mu_) {
    if (finished_) return;
    finished_ = true;
    this->Finish(final_status_);
  }

  absl::Mutex write_mu_;
  std::deque<Message> queue_ ABSL_GUARDED_BY(write_mu_);
  bool writing_ ABSL_GUARDED_BY(write_mu_) = false;
  bool closing_ ABSL_GUARDED_BY(write_mu_) = false;
  bool finished_ ABSL_GUARDED_BY(write_mu_) = false;
  grpc::Status final_status_ ABSL_GUARDED_BY(write_mu_);
};

}  // namespace semnav::reasoning
