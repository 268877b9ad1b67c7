// robot relocalize on the gateway's OperatorService: the relocalization loop on demand.
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::reasoning::v1;
using OperatorStub = api::OperatorService::Stub;

std::string LocalizationLine(const std::string& robot_id, const api::RobotLocalization& l) {
  const auto& t = l.map_from_odom().position();
  return absl::StrFormat(
      "%s: %s (trigger: %s)  reported %s  map_from_odom (%.2f, %.2f)  recoveries %d  failures "
      "%d%s\n",
      robot_id, l.relocalizing() ? "relocalizing" : "tracking",
      l.trigger().empty() ? "none" : l.trigger(), api::LocalizationStatus_Name(l.reported()), t.x(),
      t.y(), l.recoveries(), l.failures(), l.trusted() ? "" : "  POSE NOT TRUSTED");
}

int Relocalize(const Invocation& invocation) {
  if (!invocation.Has("robot")) return UsageError("robot relocalize needs --robot");
  api::RelocalizeRobotRequest request;
  request.set_request_id(invocation.RequestId());
  request.set_robot_id(invocation.Flag("robot"));
  request.set_lease_id(invocation.Flag("lease"));
  request.set_reason(invocation.Flag("reason"));
  return RunUnary<api::OperatorService>(
      invocation, Service::kGateway, &OperatorStub::RelocalizeRobot, request,
      [&](const api::RelocalizeRobotResponse& r) {
        return LocalizationLine(request.robot_id(), r.localization());
      });
}

}  // namespace

std::vector<Command> RobotCommands() {
  return {
      {"robot",
       "relocalize",
       "",
       "pause the robot's task, look around and relocalize it in its landmark map (outcome in the "
       "event log)",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "robot (required)"},
        {"lease", "LEASE_ID", "lease id, needed when the robot's lease is held"},
        {"reason", "TEXT", "why, for the event log"},
        kRequestIdFlag},
       Relocalize,
       0},
  };
}

}  // namespace semnav::cli
