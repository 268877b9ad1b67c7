// lease acquire / renew / release and estop trigger / clear on the gateway's OperatorService.
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/time/time.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/args.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::reasoning::v1;
using OperatorStub = api::OperatorService::Stub;

const FlagSpec kTtlFlag = {"ttl", "SECONDS", "time to live, 1 s to 10 min (default 30 s)"};

// Sets the request's ttl from --ttl when given.
template <typename Request>
absl::Status SetTtl(const Invocation& invocation, Request& request) {
  if (!invocation.Has("ttl")) return absl::OkStatus();
  absl::StatusOr<absl::Duration> ttl = ParseSeconds("ttl", invocation.Flag("ttl"));
  if (!ttl.ok()) return ttl.status();
  const int64_t nanos = absl::ToInt64Nanoseconds(*ttl);
  request.mutable_ttl()->set_seconds(nanos / 1000000000);
  request.mutable_ttl()->set_nanos(static_cast<int32_t>(nanos % 1000000000));
  return absl::OkStatus();
}

std::string LeaseLine(const api::Lease& lease) {
  const absl::Time expires = absl::FromUnixSeconds(lease.expires_at().seconds());
  return absl::StrCat(lease.lease_id(), "  robot ", lease.robot_id(), "  holder ", lease.holder(),
                      "  expires ",
                      absl::FormatTime("%Y-%m-%dT%H:%M:%SZ", expires, absl::UTCTimeZone()), "\n");
}

int Acquire(const Invocation& invocation) {
  if (!invocation.Has("robot") || !invocation.Has("holder"))
    return UsageError("lease acquire needs --robot and --holder");
  api::AcquireLeaseRequest request;
  request.set_request_id(invocation.RequestId());
  request.set_robot_id(invocation.Flag("robot"));
  request.set_holder(invocation.Flag("holder"));
  if (absl::Status ttl = SetTtl(invocation, request); !ttl.ok())
    return UsageError(std::string(ttl.message()));
  return RunUnary<api::OperatorService>(
      invocation, Service::kGateway, &OperatorStub::AcquireLease, request,
      [](const api::AcquireLeaseResponse& r) { return LeaseLine(r.lease()); });
}

int Renew(const Invocation& invocation) {
  api::RenewLeaseRequest request;
  request.set_lease_id(invocation.positional()[0]);
  if (absl::Status ttl = SetTtl(invocation, request); !ttl.ok())
    return UsageError(std::string(ttl.message()));
  return RunUnary<api::OperatorService>(
      invocation, Service::kGateway, &OperatorStub::RenewLease, request,
      [](const api::RenewLeaseResponse& r) { return LeaseLine(r.lease()); });
}

int Release(const Invocation& invocation) {
  api::ReleaseLeaseRequest request;
  request.set_lease_id(invocation.positional()[0]);
  return RunUnary<api::OperatorService>(invocation, Service::kGateway, &OperatorStub::ReleaseLease,
                                        request, [&](const api::ReleaseLeaseResponse&) {
                                          return absl::StrCat("released ", request.lease_id(),
                                                              "\n");
                                        });
}

int Trigger(const Invocation& invocation) {
  api::EmergencyStopRequest request;
  request.set_request_id(invocation.RequestId());
  request.set_robot_id(invocation.Flag("robot"));
  request.set_reason(invocation.Flag("reason", "emergency stop from semnavctl"));
  return RunUnary<api::OperatorService>(
      invocation, Service::kGateway, &OperatorStub::EmergencyStop, request,
      [](const api::EmergencyStopResponse& r) {
        return absl::StrCat("emergency stop: robots stopped [",
                            absl::StrJoin(r.stopped_robot_ids(), ", "), "], tasks cancelled [",
                            absl::StrJoin(r.cancelled_task_ids(), ", "), "]\n");
      });
}

int Clear(const Invocation& invocation) {
  if (!invocation.Has("robot")) return UsageError("estop clear needs --robot");
  api::ClearEmergencyStopRequest request;
  request.set_request_id(invocation.RequestId());
  request.set_robot_id(invocation.Flag("robot"));
  request.set_lease_id(invocation.Flag("lease"));
  return RunUnary<api::OperatorService>(
      invocation, Service::kGateway, &OperatorStub::ClearEmergencyStop, request,
      [&](const api::ClearEmergencyStopResponse&) {
        return absl::StrCat("emergency stop cleared for ", request.robot_id(), "\n");
      });
}

}  // namespace

std::vector<Command> LeaseCommands() {
  return {
      {"lease",
       "acquire",
       "",
       "take the exclusive control lease of a robot",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "robot to control (required)"},
        {"holder", "NAME", "holder name shown to others (required)"},
        kTtlFlag,
        kRequestIdFlag},
       Acquire,
       0},
      {"lease",
       "renew",
       "LEASE_ID",
       "extend a lease before it expires",
       Service::kGateway,
       {kTtlFlag},
       Renew,
       1},
      {"lease", "release", "LEASE_ID", "give a lease back", Service::kGateway, {}, Release, 1},
      {"estop",
       "trigger",
       "",
       "emergency stop of one robot or all: cancels their tasks, refuses new ones",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "robot to stop (default: every connected robot)"},
        {"reason", "TEXT", "why, for the event log"},
        kRequestIdFlag},
       Trigger,
       0},
      {"estop",
       "clear",
       "",
       "lift a robot's emergency stop",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "robot (required)"},
        {"lease", "LEASE_ID", "lease id, needed when the robot's lease is held"},
        kRequestIdFlag},
       Clear,
       0},
  };
}

}  // namespace semnav::cli
