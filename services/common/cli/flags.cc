#include "services/common/cli/flags.h"

#include <algorithm>
#include <cstdlib>
#include <iostream>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "services/common/cli/help.h"

namespace semnav {

std::optional<std::string> ParsedFlags::Get(const std::string& name) const {
  auto it = values.find(name);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

absl::StatusOr<ParsedFlags> ParseFlags(int argc, char** argv, int first,
                                       const std::vector<FlagSpec>& specs) {
  ParsedFlags parsed;
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (!absl::StartsWith(arg, "--")) {
      parsed.positional.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2);
    std::optional<std::string> inline_value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      inline_value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    auto spec =
        std::find_if(specs.begin(), specs.end(), [&](const FlagSpec& s) { return s.name == name; });
    if (spec == specs.end()) {
      return absl::InvalidArgumentError(absl::StrCat("unknown flag --", name, " (see --help)"));
    }
    if (spec->value_name.empty()) {
      if (inline_value) {
        return absl::InvalidArgumentError(absl::StrCat("flag --", name, " takes no value"));
      }
      parsed.values[name] = "true";
    } else if (inline_value) {
      parsed.values[name] = *inline_value;
    } else if (i + 1 < argc) {
      parsed.values[name] = argv[++i];
    } else {
      return absl::InvalidArgumentError(
          absl::StrCat("flag --", name, " needs a value ", spec->value_name));
    }
  }
  return parsed;
}

ParsedFlags ParseFlagsOrExit(int argc, char** argv, const std::vector<FlagSpec>& specs,
                             std::string_view program, std::string_view usage) {
  if (HelpRequested(argc, argv)) {
    std::cout << usage << std::flush;
    std::exit(0);
  }
  absl::StatusOr<ParsedFlags> parsed = ParseFlags(argc, argv, 1, specs);
  absl::Status error = parsed.status();
  if (parsed.ok() && !parsed->positional.empty()) {
    error = absl::InvalidArgumentError(
        absl::StrCat("unexpected argument '", parsed->positional.front(), "'"));
  }
  if (!error.ok()) {
    std::cerr << program << ": " << error.message() << "\n" << usage << std::flush;
    std::exit(2);
  }
  return *std::move(parsed);
}

std::string FlagsHelp(const std::vector<FlagSpec>& specs) {
  std::string out;
  for (const FlagSpec& spec : specs) {
    std::string left =
        absl::StrCat("  --", spec.name, spec.value_name.empty() ? "" : " ", spec.value_name);
    if (left.size() < 28) left.resize(28, ' ');
    absl::StrAppend(&out, left, " ", spec.help, "\n");
  }
  return out;
}

}  // namespace semnav
