#include "clients/cli/interrupt.h"

#include <pthread.h>
#include <signal.h>

#include <cstdlib>
#include <thread>

#include "absl/synchronization/mutex.h"

namespace semnav::cli {
namespace {

absl::Mutex mu;
grpc::ClientContext* active_context ABSL_GUARDED_BY(mu) = nullptr;
bool interrupted_flag ABSL_GUARDED_BY(mu) = false;

sigset_t InterruptSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  return signals;
}

void WaitForInterrupts() {
  const sigset_t signals = InterruptSignals();
  for (;;) {
    int signal = 0;
    if (sigwait(&signals, &signal) != 0) continue;
    absl::MutexLock lock(&mu);
    if (active_context == nullptr) std::_Exit(128 + signal);
    interrupted_flag = true;
    active_context->TryCancel();
  }
}

}  // namespace

void InstallInterruptHandler() {
  const sigset_t signals = InterruptSignals();
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread(WaitForInterrupts).detach();
}

InterruptScope::InterruptScope(grpc::ClientContext* context) {
  absl::MutexLock lock(&mu);
  active_context = context;
  interrupted_flag = false;
}

InterruptScope::~InterruptScope() {
  absl::MutexLock lock(&mu);
  active_context = nullptr;
}

bool InterruptScope::interrupted() const {
  absl::MutexLock lock(&mu);
  return interrupted_flag;
}

}  // namespace semnav::cli
