// GatewayHub: control leases and the emergency stop.
#include "absl/strings/str_cat.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

namespace {

// The lease time a request asks for, in seconds: its `ttl`, else the configured default; it must
// lie between 1 s and max_lease_ttl_s.
template <typename LeaseRequest>
absl::StatusOr<double> RequestedTtl(const LeaseRequest& request, const GatewayConfig& config) {
  double ttl = config.default_lease_ttl_s;
  if (request.has_ttl()) {
    ttl = static_cast<double>(TimeUtil::DurationToMilliseconds(request.ttl())) / 1000.0;
  }
  if (ttl < 1.0 || ttl > config.max_lease_ttl_s) {
    return FieldError(absl::StatusCode::kInvalidArgument, "ttl",
                      "must be between 1 s and max_lease_ttl_s");
  }
  return ttl;
}

}  // namespace

absl::StatusOr<api::Lease> GatewayHub::AcquireLease(const api::AcquireLeaseRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.request_id(), "request_id"); !s.ok()) return s;
  const std::string key = absl::StrCat("AcquireLease:", request.request_id());
  if (auto cached = Cached<api::Lease>(requests_, key)) return *cached;
  if (absl::Status s = Required(request.robot_id(), "robot_id"); !s.ok()) return s;
  if (absl::Status s = Required(request.holder(), "holder"); !s.ok()) return s;
  absl::StatusOr<double> ttl = RequestedTtl(request, config_);
  if (!ttl.ok()) return ttl.status();
  absl::StatusOr<LeaseInfo> lease =
      leases_.Acquire(request.robot_id(), request.holder(), absl::Seconds(*ttl), absl::Now());
  if (!lease.ok()) {
    return FieldError(absl::StatusCode::kFailedPrecondition, "robot_id", lease.status().message(),
                      "LEASE_HELD");
  }
  Log(api::EVENT_KIND_LEASE, request.robot_id(), "",
      absl::StrCat("lease acquired by ", request.holder()));
  journal_dirty_ = true;
  api::Lease out = ToProto(*lease);
  requests_.Remember(key, out.SerializeAsString());
  return out;
}

absl::StatusOr<api::Lease> GatewayHub::RenewLease(const api::RenewLeaseRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.lease_id(), "lease_id"); !s.ok()) return s;
  absl::StatusOr<double> ttl = RequestedTtl(request, config_);
  if (!ttl.ok()) return ttl.status();
  absl::StatusOr<LeaseInfo> lease =
      leases_.Renew(request.lease_id(), absl::Seconds(*ttl), absl::Now());
  if (!lease.ok())
    return FieldError(absl::StatusCode::kNotFound, "lease_id", "unknown or expired lease",
                      "NOT_FOUND");
  journal_dirty_ = true;
  return ToProto(*lease);
}

absl::Status GatewayHub::ReleaseLease(const api::ReleaseLeaseRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.lease_id(), "lease_id"); !s.ok()) return s;
  leases_.Release(request.lease_id());
  journal_dirty_ = true;
  return absl::OkStatus();
}

absl::StatusOr<api::EmergencyStopResponse> GatewayHub::EmergencyStop(
    const api::EmergencyStopRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.request_id(), "request_id"); !s.ok()) return s;
  const std::string key = absl::StrCat("EmergencyStop:", request.request_id());
  const RequestInFlight in_flight = BeginRequest(key);
  if (auto cached = Cached<api::EmergencyStopResponse>(requests_, key)) return *cached;
  if (!request.robot_id().empty()) RobotRecord(request.robot_id());
  api::EmergencyStopResponse response;
  // Robots whose task is inside a planning call get the stop at once; their task is cancelled
  // once the call ends (Apply sends nothing to a stopped robot meanwhile).
  std::vector<std::string> cancel_after_call;
  for (auto& [robot_id, robot] : robots_) {
    if (!request.robot_id().empty() && robot_id != request.robot_id()) continue;
    // "" = every connected robot: a disconnected robot's paused task is not the stop's business
    // (it stays paused until the robot reconnects or the operator acts on it by id).
    if (request.robot_id().empty() && robot.session == nullptr) continue;
    robot.emergency_stop = true;
    Task* task = tasks_.Find(robot.active_task);
    if (task != nullptr && task->in_remote_call) {
      cancel_after_call.push_back(task->task_id);
    } else if (task != nullptr && !task->executor->finished()) {
      task->executor->Cancel(absl::StrCat("emergency stop: ", request.reason()));
      response.add_cancelled_task_ids(task->task_id);
      Apply(*task, {});
    }
    if (robot.session != nullptr) {
      api::ConnectResponse stop;
      api::RobotCommand* command = stop.mutable_command();
      command->set_command_id(robot.last_session_command = robot.next_command_id++);
      command->set_reason(absl::StrCat("emergency stop: ", request.reason()));
      command->mutable_stop()->set_emergency(true);
      robot.last_command = *command;
      robot.session->Send(stop);
      response.add_stopped_robot_ids(robot_id);
    }
    Log(api::EVENT_KIND_EMERGENCY_STOP, robot_id, "",
        absl::StrCat("emergency stop: ", request.reason()));
  }
  for (const std::string& task_id : cancel_after_call) {
    Task& task = *tasks_.Find(task_id);
    AwaitExecutor(task);
    if (task.executor->finished()) continue;
    task.executor->Cancel(absl::StrCat("emergency stop: ", request.reason()));
    response.add_cancelled_task_ids(task_id);
    Apply(task, {});
  }
  requests_.Remember(key, response.SerializeAsString());
  return response;
}

absl::Status GatewayHub::ClearEmergencyStop(const api::ClearEmergencyStopRequest& request) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) return s;
  if (absl::Status s = Required(request.request_id(), "request_id"); !s.ok()) return s;
  if (absl::Status s = Required(request.robot_id(), "robot_id"); !s.ok()) return s;
  auto robot = robots_.find(request.robot_id());
  if (robot == robots_.end()) {
    return FieldError(absl::StatusCode::kNotFound, "robot_id", "unknown robot", "NOT_FOUND");
  }
  if (absl::Status s = CheckControl(request.robot_id(), request.lease_id()); !s.ok()) return s;
  if (robot->second.emergency_stop) {
    robot->second.emergency_stop = false;
    Log(api::EVENT_KIND_EMERGENCY_STOP, request.robot_id(), "", "emergency stop cleared");
  }
  return absl::OkStatus();
}

}  // namespace semnav::reasoning
