// semnav-bench-multirobot (`semnav bench multirobot`): two robots, one frame. In each generated
// home robot A surveys every room and saves its map; mapping pushes A's landmarks to the
// relocalization service by itself. Robot B then starts at random places with an unknown rigid
// offset, looks around once, is aligned to A's map with AlignMaps and goes straight to an object
// A saw. Reports alignment error, B's path against the geodesic and success over all trials
// (docs/performance/relocalization.md, "Two robots").
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "clients/sim/loop/two_robot_scenario.h"
#include "services/common/cli/executable_dir.h"
#include "services/common/cli/flags.h"

namespace {

namespace loop = semnav::sim::loop;

const std::vector<semnav::FlagSpec> kFlags = {
    {"worlds", "N", "generated homes, seeds 1..N (default 2)"},
    {"trials", "N", "robot B runs per home (default 5)"},
    {"seed", "N", "seed of B's starts, offsets and targets (default 1)"},
    {"look-arounds", "N", "look-arounds B may take before a reliable alignment (default 5)"},
    {"move-m", "M", "B's move between two look-arounds, metres by path (default 3)"},
    {"no-scan-match", "", "align B by objects alone (no MatchLostScan against A's grid)"},
    {"json", "FILE", "also write the figures as JSON"},
    {"help", "", "this text"},
};

int Fail(const absl::Status& status) {
  std::cerr << "semnav-bench-multirobot: " << status.message() << "\n";
  return 1;
}

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double Max(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}

}  // namespace

int main(int argc, char** argv) {
  const semnav::ParsedFlags flags = semnav::ParseFlagsOrExit(
      argc, argv, kFlags, "semnav-bench-multirobot",
      absl::StrCat("usage: semnav-bench-multirobot [flags]\n", semnav::FlagsHelp(kFlags),
                   "Starts relocalization and two mapping services beside this binary. Target: "
                   "B reaches A's object with a path <= 1.3x the shortest, over >= 10 trials.\n"));
  int worlds = 2;
  int trials = 5;
  uint64_t seed = 1;
  if (auto v = flags.Get("worlds");
      v && (!absl::SimpleAtoi(*v, &worlds) || worlds < 1 || worlds > 100)) {
    return Fail(absl::InvalidArgumentError("--worlds: a number in [1, 100]"));
  }
  if (auto v = flags.Get("trials");
      v && (!absl::SimpleAtoi(*v, &trials) || trials < 1 || trials > 1000)) {
    return Fail(absl::InvalidArgumentError("--trials: a number in [1, 1000]"));
  }
  if (auto v = flags.Get("seed"); v && !absl::SimpleAtoi(*v, &seed)) {
    return Fail(absl::InvalidArgumentError("--seed: not a number"));
  }
  loop::TwoRobotOptions defaults;
  if (auto v = flags.Get("look-arounds");
      v && (!absl::SimpleAtoi(*v, &defaults.max_look_arounds) || defaults.max_look_arounds < 1 ||
            defaults.max_look_arounds > 10)) {
    return Fail(absl::InvalidArgumentError("--look-arounds: a number in [1, 10]"));
  }
  if (auto v = flags.Get("move-m"); v && (!absl::SimpleAtod(*v, &defaults.move_m) ||
                                          !(defaults.move_m >= 0.5 && defaults.move_m <= 20))) {
    return Fail(absl::InvalidArgumentError("--move-m: a number in [0.5, 20]"));
  }
  defaults.scan_match = !flags.Has("no-scan-match");
  const std::string work_dir = (std::filesystem::temp_directory_path() /
                                absl::StrCat("semnav-bench-multirobot-", ::getpid()))
                                   .string();
  absl::StatusOr<std::unique_ptr<loop::TwoRobotStack>> stack =
      loop::TwoRobotStack::Start(semnav::ExecutableDir(), work_dir);
  if (!stack.ok()) return Fail(stack.status());

  nlohmann::json report;
  report["worlds"] = nlohmann::json::array();
  std::vector<double> error_m, error_deg, ratios, route_ratios, align_ms;
  int total = 0, aligned = 0, reliable = 0, succeeded = 0, within_ratio = 0;
  int scan_refined = 0, global_scan = 0;
  std::printf("%-20s %5s %-14s %4s %5s %7s %8s %8s %7s %7s %6s  %s\n", "world", "trial", "target",
              "look", "inl", "err_m", "err_deg", "path_m", "short_m", "ratio", "ok", "failure");
  for (int w = 1; w <= worlds; ++w) {
    loop::TwoRobotOptions options = defaults;
    options.world_seed = static_cast<uint64_t>(w);
    options.trials = trials;
    options.trial_seed = seed;
    absl::StatusOr<loop::TwoRobotWorldResult> result =
        loop::RunTwoRobotWorld(options, (*stack)->endpoints());
    if (!result.ok()) return Fail(result.status());
    nlohmann::json world = {{"world", result->world},
                            {"a_viewpoints", result->a_viewpoints},
                            {"a_frames", result->a_frames},
                            {"a_landmarks", result->a_landmarks},
                            {"trials", nlohmann::json::array()}};
    for (const loop::TwoRobotTrial& t : result->trials) {
      ++total;
      aligned += t.aligned ? 1 : 0;
      reliable += t.reliable ? 1 : 0;
      succeeded += t.success ? 1 : 0;
      scan_refined += t.alignment == loop::kAlignedByObjectsScanRefined ? 1 : 0;
      global_scan += t.alignment == loop::kAlignedByGlobalScanMatch ? 1 : 0;
      if (t.aligned) {
        error_m.push_back(t.alignment_error_m);
        error_deg.push_back(t.alignment_error_deg);
        align_ms.push_back(t.align_ms);
      }
      if (t.success) {
        ratios.push_back(t.path_ratio);
        route_ratios.push_back(t.route_ratio);
        within_ratio += t.path_ratio <= 1.3 ? 1 : 0;
      }
      std::printf("%-20s %5d %-14s %4d %5d %7.3f %8.2f %8.2f %7.2f %7.3f %6s  %s\n",
                  result->world.c_str(), t.index, t.target_label.c_str(), t.look_arounds, t.inliers,
                  t.alignment_error_m, t.alignment_error_deg, t.path_m, t.shortest_m, t.path_ratio,
                  t.success ? "yes" : "no",
                  absl::StrCat(t.failure,
                               t.aligned ? absl::StrFormat(" (rms %.3f m)", t.rms_residual_m) : "")
                      .c_str());
      world["trials"].push_back({{"trial", t.index},
                                 {"target_id", t.target_id},
                                 {"target_label", t.target_label},
                                 {"b_landmarks", t.b_landmarks},
                                 {"look_arounds", t.look_arounds},
                                 {"aligned", t.aligned},
                                 {"reliable", t.reliable},
                                 {"alignment", t.alignment},
                                 {"inliers", t.inliers},
                                 {"rms_residual_m", t.rms_residual_m},
                                 {"align_ms", t.align_ms},
                                 {"alignment_error_m", t.alignment_error_m},
                                 {"alignment_error_deg", t.alignment_error_deg},
                                 {"path_m", t.path_m},
                                 {"shortest_m", t.shortest_m},
                                 {"path_ratio", t.path_ratio},
                                 {"look_m", t.look_m},
                                 {"route_ratio", t.route_ratio},
                                 {"distance_to_target_m", t.distance_to_target_m},
                                 {"success", t.success},
                                 {"failure", t.failure}});
    }
    report["worlds"].push_back(world);
  }
  const double success_rate = total > 0 ? static_cast<double>(succeeded) / total : 0.0;
  // The target counts a trial only when B reached the object with a path <= 1.3x.
  const double within_ratio_rate = total > 0 ? static_cast<double>(within_ratio) / total : 0.0;
  report["summary"] = {{"trials", total},
                       {"max_look_arounds", defaults.max_look_arounds},
                       {"move_m", defaults.move_m},
                       {"aligned", aligned},
                       {"reliable", reliable},
                       {"scan_match", defaults.scan_match},
                       {"scan_refined", scan_refined},
                       {"global_scan_matches", global_scan},
                       {"success_rate", success_rate},
                       {"success_within_1_3x_rate", within_ratio_rate},
                       {"median_alignment_error_m", Median(error_m)},
                       {"max_alignment_error_m", Max(error_m)},
                       {"median_alignment_error_deg", Median(error_deg)},
                       {"max_alignment_error_deg", Max(error_deg)},
                       {"median_path_ratio", Median(ratios)},
                       {"max_path_ratio", Max(ratios)},
                       {"median_route_ratio", Median(route_ratios)},
                       {"max_route_ratio", Max(route_ratios)},
                       {"median_align_ms", Median(align_ms)}};
  std::printf(
      "\ntrials %d  aligned %d  reliable %d (scan-refined %d, global scan match %d)  success %.3f  "
      "success with path <= 1.3x %.3f\n"
      "alignment error median %.3f m / %.2f deg, max %.3f m / %.2f deg; path ratio median %.3f, "
      "max %.3f; "
      "route ratio after alignment median %.3f, max %.3f; AlignMaps median %.2f ms\n",
      total, aligned, reliable, scan_refined, global_scan, success_rate, within_ratio_rate,
      Median(error_m), Median(error_deg), Max(error_m), Max(error_deg), Median(ratios), Max(ratios),
      Median(route_ratios), Max(route_ratios), Median(align_ms));
  if (auto path = flags.Get("json")) {
    std::ofstream(*path) << report.dump(2) << "\n";
  }
  std::error_code ignored;
  stack->reset();
  std::filesystem::remove_all(work_dir, ignored);
  return 0;
}
