// semnav-bench-planning: the planning figures (Moving AI correctness and
// speed, improved Jump A* on the seed 003 map, OMPL RRT* anchor).
// Usage: semnav-bench-planning [--json FILE] [--only movingai|multimodal|rrtstar]
//          [--rrtstar_seconds S] [--threads N] [--movingai_dir DIR]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

#include "nlohmann/json.hpp"
#include "services/common/cli/help.h"
#include "services/planning/bench/movingai_suite.h"
#include "services/planning/bench/multimodal_suite.h"
#include "services/planning/bench/rrtstar_suite.h"

int main(int argc, char** argv) {
  if (semnav::HelpRequested(argc, argv)) {
    std::printf("usage: %s [--json FILE] [--only movingai|multimodal|rrtstar] [--rrtstar_seconds S]"
                " [--threads N] [--movingai_dir DIR]\n"
                "A*/JPS on every Moving AI row, multi-modal Jump A* (seed 003 Table 2) and the OMPL"
                " RRT* anchor.\n", argv[0]);
    return 0;
  }
  std::string json_path;
  std::string only;  // run one suite: movingai | multimodal | rrtstar
  double rrtstar_seconds = 3.0;
  int threads = 2;  // Moving AI rows run on this many threads
  std::string data_dir = SEMNAV_SHARED_DATA_DIR "/movingai-grid";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--json") == 0 && i + 1 < argc) {
      json_path = argv[++i];
    } else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc) {
      only = argv[++i];
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      threads = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--rrtstar_seconds") == 0 && i + 1 < argc) {
      rrtstar_seconds = std::atof(argv[++i]);
    } else if (std::strcmp(argv[i], "--movingai_dir") == 0 && i + 1 < argc) {
      data_dir = argv[++i];
    } else if (std::strncmp(argv[i], "--benchmark_", 12) != 0) {
      std::fprintf(stderr,
                   "usage: %s [--json FILE] [--only movingai|multimodal|rrtstar]"
                   " [--rrtstar_seconds S] [--threads N] [--movingai_dir DIR]\n",
                   argv[0]);
      return 2;
    }
  }
  nlohmann::json figures = nlohmann::json::object();
  if (only.empty() || only == "movingai") {
    figures.update(semnav::planning::bench::RunMovingAiSuite(data_dir, threads));
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
