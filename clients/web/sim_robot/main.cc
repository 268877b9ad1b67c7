// semnav-dashboard-sim-robot: a simulated robot that stays connected to a stack and does what
// operators tell it (from the dashboard or semnavctl), in real time. It holds a gateway session,
// streams depth/RGB frames to mapping and executes the gateway's commands in a generated home.
// With --start-stack it first starts mapping, planning and the gateway on free loopback ports.
#include <signal.h>
#include <sys/prctl.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <thread>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/core/sim_robot.h"
#include "clients/sim/loop/command_executor.h"
#include "clients/sim/loop/frame_encoder.h"
#include "clients/sim/loop/frame_stream.h"
#include "clients/sim/loop/robot_messages.h"
#include "clients/sim/loop/robot_session.h"
#include "clients/sim/loop/sim_stack.h"
#include "clients/sim/loop/smoke_episode.h"
#include "services/common/cli/executable_dir.h"
#include "services/common/cli/flags.h"

namespace {

namespace loop = semnav::sim::loop;
namespace sim = semnav::sim;
namespace api = semnav::reasoning::v1;

const std::vector<semnav::FlagSpec> kFlags = {
    {"start-stack", "",
     "start mapping, planning and the gateway (free loopback ports) beside this binary"},
    {"work-dir", "DIR",
     "configs and map store of --start-stack (default ./semnav_dashboard_stack)"},
    {"gateway", "ADDR", "gateway to connect to without --start-stack (default 127.0.0.1:50050)"},
    {"mapping", "ADDR", "mapping service (default 127.0.0.1:50051)"},
    {"planning", "ADDR", "planning service, the robot's local planner (default 127.0.0.1:50052)"},
    {"robot-id", "ID", "robot id on the session (default sim-robot)"},
    {"world-seed", "N", "seed of the generated home (default 7)"},
    {"speed", "X", "simulated seconds per wall second (default 1)"},
    {"help", "", "this text"},
};

constexpr double kStepS = 0.25;  // simulated seconds per step, one frame per step
constexpr absl::Duration kCommandWait = absl::Milliseconds(5);

std::atomic<bool> stop_requested{false};

// A task's final STOP must not end the simulated robot's life as it ends an episode: here it
// only halts the robot (the emergency form), which keeps it ready for the next task.
api::RobotCommand KeepAlive(api::RobotCommand command) {
  if (command.has_stop()) command.mutable_stop()->set_emergency(true);
  return command;
}

// Bad flags exit with 2 (usage), everything else with 1.
int Fail(const absl::Status& status) {
  std::cerr << "semnav-dashboard-sim-robot: " << status << "\n";
  return absl::IsInvalidArgument(status) ? 2 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  const semnav::ParsedFlags flags = semnav::ParseFlagsOrExit(
      argc, argv, kFlags, "semnav-dashboard-sim-robot",
      absl::StrCat("usage: semnav-dashboard-sim-robot [flags]\n", semnav::FlagsHelp(kFlags),
                   "Prints one JSON line with the endpoints, robot id and the world's nearest "
                   "object, then runs until SIGINT/SIGTERM.\n"));
  uint64_t world_seed = 7;
  double speed = 1.0;
  if (auto v = flags.Get("world-seed"); v && !absl::SimpleAtoi(*v, &world_seed)) {
    return Fail(absl::InvalidArgumentError("--world-seed: not a number"));
  }
  if (auto v = flags.Get("speed"); v && (!absl::SimpleAtod(*v, &speed) || speed <= 0)) {
    return Fail(absl::InvalidArgumentError("--speed: must be a number > 0"));
  }
  const std::string robot_id = flags.Get("robot-id").value_or("sim-robot");
  // A test harness that dies must not leave the robot (and its stack) behind.
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  signal(SIGINT, [](int) { stop_requested = true; });
  signal(SIGTERM, [](int) { stop_requested = true; });

  absl::StatusOr<loop::EpisodeSpec> spec = loop::SmokeEpisode(world_seed);
  if (!spec.ok()) return Fail(spec.status());
  std::unique_ptr<loop::SimStack> stack;
  std::string gateway = flags.Get("gateway").value_or("127.0.0.1:50050");
  std::string mapping = flags.Get("mapping").value_or("127.0.0.1:50051");
  std::string planning = flags.Get("planning").value_or("127.0.0.1:50052");
  if (flags.Has("start-stack")) {
    const std::string bin_dir = semnav::ExecutableDir();
    const std::string work_dir =
        std::filesystem::absolute(flags.Get("work-dir").value_or("semnav_dashboard_stack"))
            .string();
    loop::SimStackOptions options;
    options.bin_dir = bin_dir;
    options.work_dir = work_dir;
    absl::StatusOr<std::unique_ptr<loop::SimStack>> started = loop::SimStack::Start(options);
    if (!started.ok()) return Fail(started.status());
    stack = std::move(*started);
    gateway = stack->gateway_address();
    mapping = stack->mapping_address();
    planning = stack->planning_address();
  }
  auto channel = [](const std::string& address) {
    return grpc::CreateChannel(address, grpc::InsecureChannelCredentials());
  };
  const loop::Endpoints endpoints{channel(gateway), channel(mapping), channel(planning), nullptr};

  const sim::StartPose& start = spec->world.starts[spec->start_index];
  const sim::Scene scene = sim::Scene::Build(spec->world);
  sim::RobotConfig robot_config = sim::RobotConfig::ForModality(start.modality);
  if (start.modality == sim::Modality::kGround)
    robot_config.camera_pitch = spec->ground_camera_pitch;
  sim::SimRobot robot(spec->world, scene, start, robot_config, spec->sensors, spec->seed);
  loop::CommandExecutor executor(robot,
                                 loop::LiveMapPlanner(endpoints.planning, robot_config.radius));
  absl::StatusOr<std::unique_ptr<loop::RobotSession>> session = loop::RobotSession::Open(
      endpoints.gateway, loop::Hello(robot_id, start.modality, robot_config));
  if (!session.ok()) return Fail(session.status());
  loop::FrameStream frames(endpoints.mapping);

  std::cout
      << absl::StrFormat(
             R"({"gateway":"%s","mapping":"%s","planning":"%s","robot_id":"%s","world":"%s","nearest_object":"%s"})",
             gateway, mapping, planning, robot_id, spec->world.name, spec->target)
      << std::endl;
  auto next = std::chrono::steady_clock::now();
  const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double>(kStepS / speed));
  while (!stop_requested) {
    for (const api::RobotCommand& command : (*session)->TakeCommands(kCommandWait)) {
      if (absl::Status s =
              (*session)->Send(loop::FeedbackMessage(executor.Start(KeepAlive(command))));
          !s.ok()) {
        return Fail(s);
      }
    }
    if (std::optional<loop::Feedback> outcome = executor.Step(kStepS); outcome.has_value()) {
      if (absl::Status s = (*session)->Send(loop::FeedbackMessage(*outcome)); !s.ok())
        return Fail(s);
    }
    if (absl::Status s = (*session)->Send(loop::StateMessage(robot, robot_id)); !s.ok())
      return Fail(s);
    if (absl::StatusOr<semnav::mapping::v1::FrameAck> ack =
            frames.Send(loop::EncodeFrame(robot.Capture(), robot_id));
        !ack.ok()) {
      return Fail(ack.status());
    }
    next += period;
    std::this_thread::sleep_until(next);
  }
  return 0;
}
