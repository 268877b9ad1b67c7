// A semnavctl subcommand: `semnavctl <group> <verb> [ARGS] [flags]`.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "clients/cli/invocation.h"
#include "services/common/cli/flags.h"

namespace semnav::cli {

struct Command {
  std::string group;    // "task"
  std::string verb;     // "submit"
  std::string args;     // positional arguments for usage, e.g. "TASK_ID"
  std::string summary;  // one line
  Service service;      // the service --addr names
  std::vector<FlagSpec> flags;
  std::function<int(const Invocation&)> run;  // returns the exit code
  std::size_t positional_count = 0;  // exact number of positional arguments (instruction: >= 1)
  bool variadic = false;             // positional_count is a minimum
};

inline const FlagSpec kRequestIdFlag = {"request-id", "ID",
                                        "idempotency key (default: a fresh random id)"};

// The command groups, each in its own file.
std::vector<Command> TaskCommands();
std::vector<Command> LeaseCommands();
std::vector<Command> EventCommands();
std::vector<Command> SceneCommands();
std::vector<Command> MapCommands();
std::vector<Command> PlanCommands();
std::vector<Command> RelocalizationCommands();
std::vector<Command> RobotCommands();
std::vector<Command> HealthCommands();

}  // namespace semnav::cli
