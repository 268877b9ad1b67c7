#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav {

// One command-line flag: `--name VALUE`, `--name=VALUE`, or a bare switch `--name`.
struct FlagSpec {
  std::string name;
  std::string value_name;  // empty for a switch
  std::string help;
};

struct ParsedFlags {
  std::map<std::string, std::string> values;  // switches map to "true"
  std::vector<std::string> positional;
  bool Has(const std::string& name) const { return values.contains(name); }
  std::optional<std::string> Get(const std::string& name) const;
};

// Parses argv[first..argc). Unknown flags and missing values are INVALID_ARGUMENT naming the flag.
absl::StatusOr<ParsedFlags> ParseFlags(int argc, char** argv, int first,
                                       const std::vector<FlagSpec>& specs);

// The command line of a program without subcommands, read alike by every semnav binary: --help
// or -h anywhere prints `usage` to stdout and exits 0; an unknown flag, a flag without its value
// or a positional argument prints "<program>: <reason>" and then `usage` to stderr and exits 2.
ParsedFlags ParseFlagsOrExit(int argc, char** argv, const std::vector<FlagSpec>& specs,
                             std::string_view program, std::string_view usage);

// "  --name VALUE   help" lines for --help output.
std::string FlagsHelp(const std::vector<FlagSpec>& specs);

}  // namespace semnav
