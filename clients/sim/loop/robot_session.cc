#include "clients/sim/loop/robot_session.h"

#include "absl/strings/str_cat.h"

namespace semnav::sim::loop {

namespace api = semnav::reasoning::v1;

absl::StatusOr<std::unique_ptr<RobotSession>> RobotSession::Open(
    const std::shared_ptr<grpc::Channel>& gateway, const api::SessionHello& hello) {
  std::unique_ptr<RobotSession> session(new RobotSession());
  session->stub_ = api::RobotSessionService::NewStub(gateway);
  session->stream_ = session->stub_->Connect(&session->context_);
  api::ConnectRequest first;
  *first.mutable_hello() = hello;
  if (!session->stream_->Write(first))
    return absl::UnavailableError("gateway closed the robot session");
  api::ConnectResponse answer;
  const bool read_ok = session->stream_->Read(&answer);
  if (!read_ok || !answer.has_accepted()) {
    grpc::Status status = session->stream_->Finish();
    return absl::UnavailableError(
        absl::StrCat("robot session not accepted: ", status.error_message()));
  }
  session->reader_ = std::thread([s = session.get()] { s->ReadLoop(); });
  return session;
}

RobotSession::~RobotSession() {
  if (stream_ != nullptr) {
    stream_->WritesDone();
    context_.TryCancel();
  }
  if (reader_.joinable()) reader_.join();
  if (stream_ != nullptr) stream_->Finish();
}

void RobotSession::ReadLoop() {
  api::ConnectResponse response;
  while (stream_->Read(&response)) {
    absl::MutexLock lock(&mu_);
    if (response.has_step_done()) {
      step_done_ = true;
      last_step_done_ = response.step_done().step();
      commands_before_done_ = commands_.size();
    }
    if (response.has_command()) commands_.push_back({response.command(), absl::Now()});
    if (response.has_localization()) localization_ = response.localization();
  }
  absl::MutexLock lock(&mu_);
  closed_ = true;
}

absl::Status RobotSession::Send(const api::ConnectRequest& request) {
  if (!stream_->Write(request)) return absl::UnavailableError("gateway closed the robot session");
  return absl::OkStatus();
}

std::vector<api::RobotCommand> RobotSession::TakeCommands(absl::Duration wait) {
  std::vector<api::RobotCommand> out;
  for (ReceivedCommand& received : TakeReceivedCommands(wait)) {
    out.push_back(std::move(received.command));
  }
  return out;
}

std::vector<ReceivedCommand> RobotSession::TakeReceivedCommands(absl::Duration wait) {
  absl::MutexLock lock(&mu_);
  auto ready = [this]() ABSL_SHARED_LOCKS_REQUIRED(mu_) { return !commands_.empty() || closed_; };
  mu_.AwaitWithTimeout(absl::Condition(&ready), wait);
  std::vector<ReceivedCommand> out(commands_.begin(), commands_.end());
  commands_.clear();
  commands_before_done_ = 0;
  return out;
}

absl::StatusOr<std::vector<api::RobotCommand>> RobotSession::TakeStepCommands(
    uint64_t step, absl::Duration timeout) {
  absl::MutexLock lock(&mu_);
  auto done = [this, step]() ABSL_SHARED_LOCKS_REQUIRED(mu_) {
    return (step_done_ && last_step_done_ >= step) || closed_;
  };
  if (!mu_.AwaitWithTimeout(absl::Condition(&done), timeout)) {
    return absl::DeadlineExceededError(absl::StrCat("the gateway did not finish step ", step,
                                                    " within ", absl::FormatDuration(timeout),
                                                    " of wall time"));
  }
  if (!(step_done_ && last_step_done_ >= step)) {
    return absl::UnavailableError(
        absl::StrCat("the gateway ended the robot session before step ", step));
  }
  std::vector<api::RobotCommand> out;
  for (std::size_t i = 0; i < commands_before_done_; ++i) {
    out.push_back(std::move(commands_.front().command));
    commands_.pop_front();
  }
  commands_before_done_ = 0;
  return out;
}

bool RobotSession::closed() {
  absl::MutexLock lock(&mu_);
  return closed_;
}

}  // namespace semnav::sim::loop

namespace semnav::sim::loop {

std::optional<semnav::reasoning::v1::LocalizationUpdate> RobotSession::TakeLocalization() {
  absl::MutexLock lock(&mu_);
  std::optional<semnav::reasoning::v1::LocalizationUpdate> out = std::move(localization_);
  localization_.reset();
  return out;
}

}  // namespace semnav::sim::loop
