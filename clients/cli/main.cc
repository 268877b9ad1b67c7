// semnavctl: every operator action from a terminal, over the services' public gRPC APIs.
#include <iostream>

#include "absl/strings/str_cat.h"
#include "clients/cli/command.h"
#include "clients/cli/core/exit_codes.h"
#include "clients/cli/interrupt.h"
#include "clients/cli/output.h"
#include "services/common/cli/help.h"

namespace semnav::cli {
namespace {

std::vector<Command> AllCommands() {
  std::vector<Command> all;
  for (auto group : {TaskCommands, LeaseCommands, EventCommands, SceneCommands, MapCommands,
                     PlanCommands, RelocalizationCommands, RobotCommands, HealthCommands}) {
    for (Command& command : group()) all.push_back(std::move(command));
  }
  return all;
}

std::string Name(const Command& command) {
  return command.verb.empty() ? command.group : absl::StrCat(command.group, " ", command.verb);
}

std::string Usage(const std::vector<Command>& commands) {
  std::string out =
      "Usage: semnavctl <group> <verb> [ARGS] [flags]   (semnavctl <group> <verb> --help for "
      "details)\n\n";
  absl::StrAppend(&out, "Commands:\n");
  for (const Command& command : commands) {
    std::string left =
        absl::StrCat("  ", Name(command), command.args.empty() ? "" : " ", command.args);
    if (left.size() < 34) left.resize(34, ' ');
    absl::StrAppend(&out, left, " ", command.summary, "\n");
  }
  absl::StrAppend(&out, "\nFlags of every command:\n", FlagsHelp(ConnectionFlags()));
  absl::StrAppend(&out, "\nExit codes:\n", ExitCodeHelp());
  absl::StrAppend(&out, "\nDefault addresses are deploy/local.yaml's. docs/cli.md has examples.\n");
  return out;
}

std::string CommandHelp(const Command& command) {
  std::string out =
      absl::StrCat("Usage: semnavctl ", Name(command), command.args.empty() ? "" : " ",
                   command.args, " [flags]\n\n", command.summary, "\n");
  if (!command.flags.empty()) absl::StrAppend(&out, "\nFlags:\n", FlagsHelp(command.flags));
  absl::StrAppend(&out, "\nConnection and output flags (", InfoOf(command.service).name,
                  " is the --addr service):\n", FlagsHelp(ConnectionFlags()), "\nExit codes:\n",
                  ExitCodeHelp());
  return out;
}

bool IsHelp(const std::string& arg) { return arg == "--help" || arg == "-h" || arg == "help"; }

int Main(int argc, char** argv) {
  const std::vector<Command> commands = AllCommands();
  if (argc < 2 || IsHelp(argv[1])) {
    std::cout << Usage(commands);
    return argc < 2 ? ToInt(ExitCode::kUsage) : ToInt(ExitCode::kOk);
  }
  const std::string group = argv[1];
  const std::string verb = argc > 2 ? argv[2] : "";
  const Command* found = nullptr;
  for (const Command& command : commands) {
    if (command.group == group && (command.verb.empty() || command.verb == verb)) found = &command;
  }
  if (found == nullptr) {
    std::cerr << "semnavctl: unknown command '" << group << (verb.empty() ? "" : " ") << verb
              << "'\n\n"
              << Usage(commands);
    return ToInt(ExitCode::kUsage);
  }
  const int first = found->verb.empty() ? 2 : 3;
  if (HelpRequested(argc, argv)) {
    std::cout << CommandHelp(*found);
    return ToInt(ExitCode::kOk);
  }
  // A malformed command line gets the reason, then the command's usage.
  auto usage_error = [&](const std::string& reason) {
    const int code = UsageError(reason);
    std::cerr << "\n" << CommandHelp(*found);
    return code;
  };
  absl::StatusOr<Invocation> invocation =
      Invocation::Parse(argc, argv, first, found->flags, found->service);
  if (!invocation.ok()) return usage_error(std::string(invocation.status().message()));
  const std::size_t given = invocation->positional().size();
  if (given < found->positional_count || (!found->variadic && given > found->positional_count)) {
    return usage_error(absl::StrCat(Name(*found), " takes ", found->variadic ? "at least " : "",
                                    found->positional_count,
                                    " argument(s): ", found->args.empty() ? "none" : found->args));
  }
  return found->run(*invocation);
}

}  // namespace
}  // namespace semnav::cli

int main(int argc, char** argv) {
  semnav::cli::InstallInterruptHandler();
  return semnav::cli::Main(argc, argv);
}
