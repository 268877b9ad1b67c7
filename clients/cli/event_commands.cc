// events watch: the gateway's event log, replayed after an id, then live.
#include <iostream>

#include "absl/time/time.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/args.h"
#include "clients/cli/core/exit_codes.h"
#include "clients/cli/core/table.h"
#include "clients/cli/interrupt.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::reasoning::v1;

std::string EventLine(const api::Event& event) {
  const absl::Time time =
      absl::FromUnixNanos(event.time().seconds() * 1000000000 + event.time().nanos());
  std::string line = absl::StrCat(
      event.event_id(), "  ", absl::FormatTime("%Y-%m-%dT%H:%M:%E3SZ", time, absl::UTCTimeZone()),
      "  ", ShortEnumName(api::EventKind_Name(event.kind()), "EVENT_KIND_"));
  if (!event.robot_id().empty()) absl::StrAppend(&line, "  robot=", event.robot_id());
  if (!event.task_id().empty()) absl::StrAppend(&line, "  task=", event.task_id());
  absl::StrAppend(&line, "  ", event.message());
  return line;
}

int Watch(const Invocation& invocation) {
  api::StreamEventsRequest request;
  request.set_robot_id(invocation.Flag("robot"));
  int64_t count = 0;  // 0 = until Ctrl-C or the deadline
  if (invocation.Has("since")) {
    absl::StatusOr<int64_t> since = ParseCount("since", invocation.Flag("since"), 0);
    if (!since.ok()) return UsageError(std::string(since.status().message()));
    request.set_last_event_id(static_cast<uint64_t>(*since));
  }
  if (invocation.Has("count")) {
    absl::StatusOr<int64_t> parsed = ParseCount("count", invocation.Flag("count"), 1);
    if (!parsed.ok()) return UsageError(std::string(parsed.status().message()));
    count = *parsed;
  }
  return WithStub<api::OperatorService>(
      invocation, Service::kGateway, [&](api::OperatorService::Stub& stub) {
        grpc::ClientContext context;
        invocation.SetDeadline(context, std::nullopt);
        InterruptScope interrupt(&context);
        auto reader = stub.StreamEvents(&context, request);
        int64_t seen = 0;
        for (api::StreamEventsResponse response;
             (count == 0 || seen < count) && reader->Read(&response); ++seen) {
          if (invocation.json()) {
            PrintJson(response);
            continue;
          }
          if (response.replay_truncated())
            std::cout << "(events before " << response.event().event_id() << " dropped)\n";
          std::cout << EventLine(response.event()) << std::endl;
        }
        if (count > 0 && seen == count) {
          context.TryCancel();
          reader->Finish();
          return ToInt(ExitCode::kOk);
        }
        const grpc::Status finished = reader->Finish();
        if (interrupt.interrupted() || finished.ok()) return ToInt(ExitCode::kOk);
        return Fail(FromGrpcStatus(finished));
      });
}

}  // namespace

std::vector<Command> EventCommands() {
  return {
      {"events",
       "watch",
       "",
       "the event log: events after --since, then live ones (Ctrl-C stops)",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "only this robot's events"},
        {"since", "EVENT_ID", "replay retained events after this id (default 0: only live events)"},
        {"count", "N", "stop after N events"}},
       Watch,
       0},
  };
}

}  // namespace semnav::cli
