// task submit / get / list / watch / cancel / pause / resume on the gateway's OperatorService.
#include <unistd.h>

#include <iostream>

#include "absl/strings/str_join.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/table.h"
#include "clients/cli/interrupt.h"
#include "clients/cli/task_view.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"

namespace semnav::cli {
namespace {

using reasoning_api::OperatorService;
using OperatorStub = OperatorService::Stub;

const FlagSpec kLeaseFlag = {"lease", "LEASE_ID",
                             "lease id, needed when the robot's lease is held"};

// Follows a task's snapshots until it finishes, Ctrl-C or --deadline.
int FollowTask(const Invocation& invocation, OperatorStub& stub, const std::string& task_id) {
  grpc::ClientContext context;
  invocation.SetDeadline(context, std::nullopt);
  InterruptScope interrupt(&context);
  reasoning_api::WatchTaskRequest request;
  request.set_task_id(task_id);
  auto reader = stub.WatchTask(&context, request);
  ProgressPrinter printer(std::cout, !invocation.json() && isatty(STDOUT_FILENO));
  reasoning_api::TaskStatus last_status = reasoning_api::TASK_STATUS_UNSPECIFIED;
  for (reasoning_api::WatchTaskResponse update; reader->Read(&update);) {
    last_status = update.task().status();
    if (invocation.json()) {
      PrintJson(update.task());
    } else {
      printer.Show(FormatProgressLine(ToProgress(update.task())));
    }
  }
  const grpc::Status finished = reader->Finish();
  printer.Finish();
  if (interrupt.interrupted()) {
    std::cerr << "detached; the task goes on (semnavctl task watch " << task_id << ")" << std::endl;
    return ToInt(ExitCode::kOk);
  }
  if (!finished.ok()) return Fail(FromGrpcStatus(finished));
  return ToInt(ExitCodeForTask(last_status));
}

int Submit(const Invocation& invocation) {
  if (!invocation.Has("robot")) return UsageError("task submit needs --robot");
  return WithStub<OperatorService>(invocation, Service::kGateway, [&](OperatorStub& stub) {
    reasoning_api::SubmitInstructionRequest request;
    request.set_request_id(invocation.RequestId());
    request.set_robot_id(invocation.Flag("robot"));
    request.set_instruction(absl::StrJoin(invocation.positional(), " "));
    request.set_lease_id(invocation.Flag("lease"));
    request.set_allow_correction(invocation.Has("correction"));
    reasoning_api::SubmitInstructionResponse response;
    if (auto s = CallUnary(invocation, stub, &OperatorStub::SubmitInstruction, request, &response);
        !s.ok()) {
      return Fail(s);
    }
    if (invocation.Has("no-follow")) {
      if (invocation.json()) {
        PrintJson(response);
      } else {
        std::cout << FormatProgressLine(ToProgress(response.task()))
                  << (response.correction_applied() ? "  (correction applied)" : "") << std::endl;
      }
      return ToInt(ExitCode::kOk);
    }
    if (!invocation.json())
      std::cerr << "following " << response.task_id() << "; Ctrl-C detaches" << std::endl;
    return FollowTask(invocation, stub, response.task_id());
  });
}

int Get(const Invocation& invocation) {
  reasoning_api::GetTaskRequest request;
  request.set_task_id(invocation.positional()[0]);
  return RunUnary<OperatorService>(
      invocation, Service::kGateway, &OperatorStub::GetTask, request,
      [](const reasoning_api::GetTaskResponse& r) { return DescribeTask(r.task()); });
}

int List(const Invocation& invocation) {
  reasoning_api::ListTasksRequest request;
  request.set_robot_id(invocation.Flag("robot"));
  request.set_unfinished_only(invocation.Has("unfinished"));
  return RunUnary<OperatorService>(
      invocation, Service::kGateway, &OperatorStub::ListTasks, request,
      [](const reasoning_api::ListTasksResponse& r) {
        Table table({"TASK", "ROBOT", "STATUS", "PROGRESS", "STEP", "INSTRUCTION"});
        for (const reasoning_api::TaskSnapshot& task : r.tasks()) {
          const TaskProgress progress = ToProgress(task);
          table.AddRow({task.task_id(), task.robot_id(), progress.status,
                        std::to_string(static_cast<int>(task.progress() * 100.0 + 0.5)),
                        progress.step, task.instruction()});
        }
        return table.Render();
      });
}

int Watch(const Invocation& invocation) {
  return WithStub<OperatorService>(invocation, Service::kGateway, [&](OperatorStub& stub) {
    return FollowTask(invocation, stub, invocation.positional()[0]);
  });
}

// cancel, pause and resume: same request fields, a snapshot back.
template <typename Request, typename Response>
int Control(const Invocation& invocation,
            grpc::Status (OperatorStub::*method)(grpc::ClientContext*, const Request&, Response*),
            void (*extra)(const Invocation&, Request&)) {
  Request request;
  request.set_request_id(invocation.RequestId());
  request.set_task_id(invocation.positional()[0]);
  request.set_lease_id(invocation.Flag("lease"));
  if (extra != nullptr) extra(invocation, request);
  return RunUnary<OperatorService>(
      invocation, Service::kGateway, method, request,
      [](const Response& r) { return FormatProgressLine(ToProgress(r.task())) + "\n"; });
}

void SetReason(const Invocation& invocation, reasoning_api::CancelTaskRequest& request) {
  request.set_reason(invocation.Flag("reason", "cancelled with semnavctl"));
}

}  // namespace

std::vector<Command> TaskCommands() {
  return {
      {"task",
       "submit",
       "INSTRUCTION...",
       "submit an instruction and follow the task with a live progress line until it ends (Ctrl-C "
       "detaches)",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "robot to drive (required)"},
        kLeaseFlag,
        {"correction", "",
         "let the text refine the robot's active task when it reads as a correction"},
        {"no-follow", "", "print the new task and return at once"},
        kRequestIdFlag},
       Submit,
       1,
       true},
      {"task",
       "get",
       "TASK_ID",
       "a task's state, subgoals and resolved target",
       Service::kGateway,
       {},
       Get,
       1},
      {"task",
       "list",
       "",
       "the gateway's tasks, oldest first",
       Service::kGateway,
       {{"robot", "ROBOT_ID", "only this robot's tasks"},
        {"unfinished", "", "only PENDING, RUNNING, PAUSED tasks"}},
       List,
       0},
      {"task",
       "watch",
       "TASK_ID",
       "follow a task with a live progress line until it ends (Ctrl-C detaches)",
       Service::kGateway,
       {},
       Watch,
       1},
      {"task",
       "cancel",
       "TASK_ID",
       "cancel a task; the robot stops",
       Service::kGateway,
       {kLeaseFlag, {"reason", "TEXT", "why, for the event log"}, kRequestIdFlag},
       [](const Invocation& i) {
         return Control<reasoning_api::CancelTaskRequest, reasoning_api::CancelTaskResponse>(
             i, &OperatorStub::CancelTask, SetReason);
       },
       1},
      {"task",
       "pause",
       "TASK_ID",
       "pause a running task; the robot holds",
       Service::kGateway,
       {kLeaseFlag, kRequestIdFlag},
       [](const Invocation& i) {
         return Control<reasoning_api::PauseTaskRequest, reasoning_api::PauseTaskResponse>(
             i, &OperatorStub::PauseTask, nullptr);
       },
       1},
      {"task",
       "resume",
       "TASK_ID",
       "resume a paused task from its current subgoal",
       Service::kGateway,
       {kLeaseFlag, kRequestIdFlag},
       [](const Invocation& i) {
         return Control<reasoning_api::ResumeTaskRequest, reasoning_api::ResumeTaskResponse>(
             i, &OperatorStub::ResumeTask, nullptr);
       },
       1},
  };
}

}  // namespace semnav::cli
