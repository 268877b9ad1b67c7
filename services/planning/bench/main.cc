// semnav-bench-planning: the planning figures (Moving AI correctness and
// speed, improved Jump A* on the seed 003 map, OMPL RRT* anchor).
// Usage: semnav-bench-planning [--json FILE] [--only movingai|gridplanner|multimodal|rrtstar]
//          [--rrtstar_seconds S] [--threads N] [--movingai_dir DIR]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"
#include "services/common/cli/flags.h"
#include "services/planning/bench/grid_planner_suite.h"
#include "services/planning/bench/movingai_suite.h"
#include "services/planning/bench/multimodal_suite.h"
#include "services/planning/bench/rrtstar_suite.h"

namespace {

const std::vector<semnav::FlagSpec> kFlags = {{"json", "FILE", ""},
                                              {"only", "SUITE", ""},
                                              {"threads", "N", ""},
                                              {"rrtstar_seconds", "S", ""},
                                              {"movingai_dir", "DIR", ""}};

}  // namespace

int main(int argc, char** argv) {
  const std::string usage = absl::StrCat(
      "usage: ", argv[0],
      " [--json FILE] [--only movingai|gridplanner|multimodal|rrtstar] [--rrtstar_seconds S]"
      " [--threads N] [--movingai_dir DIR]\n"
      "A*/JPS on every Moving AI row, multi-modal Jump A* (seed 003 Table 2) and the"
      " OMPL RRT* anchor.\n");
  // `semnav bench` callers may pass Google Benchmark's --benchmark_* flags to every bench; this
  // one has no Google Benchmark part and ignores them.
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (i == 0 || !absl::StartsWith(argv[i], "--benchmark_")) args.push_back(argv[i]);
  }
  const semnav::ParsedFlags flags = semnav::ParseFlagsOrExit(
      static_cast<int>(args.size()), args.data(), kFlags, "semnav-bench-planning", usage);
  const std::string json_path = flags.Get("json").value_or("");
  const std::string only = flags.Get("only").value_or("");  // movingai | multimodal | rrtstar
  const double rrtstar_seconds = std::atof(flags.Get("rrtstar_seconds").value_or("3").c_str());
  // Moving AI rows run on this many threads.
  const int threads = std::max(1, std::atoi(flags.Get("threads").value_or("2").c_str()));
  const std::string data_dir =
      flags.Get("movingai_dir").value_or(SEMNAV_SHARED_DATA_DIR "/movingai-grid");
  nlohmann::json figures = nlohmann::json::object();
  if (only.empty() || only == "movingai") {
    figures.update(semnav::planning::bench::RunMovingAiSuite(data_dir, threads));
  }
  if (only.empty() || only == "gridplanner") {
    figures.update(semnav::planning::bench::RunGridPlannerSuite(data_dir));
  }
  if (only.empty() || only == "multimodal") {
    figures.update(semnav::planning::bench::RunMultiModalSuite());
  }
  if (only.empty() || only == "rrtstar") {
    figures.update(semnav::planning::bench::RunRrtStarSuite(rrtstar_seconds));
  }
  if (!json_path.empty()) {
    std::ofstream(json_path) << figures.dump(2) << "\n";
  }
  return 0;
}
