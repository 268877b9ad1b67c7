// Flag parsing of the benches built on Google Benchmark: --help before benchmark::Initialize
// (which would answer it with its own text), then Initialize takes its --benchmark_* flags out
// of argv, then the bench's own flags, refusing anything else with exit code 2.
#pragma once

#include <benchmark/benchmark.h>

#include <iostream>
#include <string_view>
#include <vector>

#include "services/common/cli/flags.h"
#include "services/common/cli/help.h"

namespace semnav {

inline ParsedFlags ParseBenchmarkFlagsOrExit(int* argc, char** argv,
                                             const std::vector<FlagSpec>& specs,
                                             std::string_view program, std::string_view usage) {
  if (HelpRequested(*argc, argv)) {
    std::cout << usage;
    std::exit(0);
  }
  benchmark::Initialize(argc, argv);
  return ParseFlagsOrExit(*argc, argv, specs, program, usage);
}

}  // namespace semnav
