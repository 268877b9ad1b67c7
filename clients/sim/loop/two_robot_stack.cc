#include "clients/sim/loop/two_robot_stack.h"

#include <grpcpp/grpcpp.h>

#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "services/launcher/free_port.h"

namespace semnav::sim::loop {
namespace {

std::string WriteConfig(const std::string& dir, const std::string& name, const std::string& yaml) {
  const std::string path = dir + "/" + name + ".yaml";
  std::ofstream(path) << yaml;
  return path;
}

// Robot `name`'s mapping: its live landmarks go to relocalization under map id `name` every 0.5 s.
std::string MappingYaml(const std::string& work_dir, const std::string& name,
                        const std::string& relocalization) {
  return absl::StrCat("mapping:\n  store_directory: ", work_dir, "/maps_", name,
                      "\n  live_snapshot_interval_s: 0\n  landmarks:\n    live_map_id: ", name,
                      "\n    interval_s: 0.5\n    relocalization:\n      address: ", relocalization,
                      "\n");
}

// Relocalization tuned for landmark maps built by mapping (docs/algorithms/relocalization.md,
// "Landmark maps from the scene graph"): instance centres from partial views of the same object
// differ by up to ~0.4 m between robots, and a room holds a handful of objects, not a shelf.
constexpr char kObjectMapRelocalizationYaml[] = R"(relocalization:
  matching: {pos_sigma_m: 0.5, min_neighbour_matches: 2, rematch_radius_m: 1.0}
  pose: {outlier_distance_m: 1.0}
  final_residual_gate_m: 0.8
  reliability: {min_inliers: 4, max_rms_m: 0.4, translation_m: 2.0, rotation_deg: 30}
)";

}  // namespace

absl::StatusOr<std::unique_ptr<TwoRobotStack>> TwoRobotStack::Start(const std::string& bin_dir,
                                                                    const std::string& work_dir) {
  std::error_code error;
  std::filesystem::create_directories(work_dir, error);
  if (error)
    return absl::InternalError(absl::StrCat("cannot create ", work_dir, ": ", error.message()));
  std::unique_ptr<TwoRobotStack> stack(new TwoRobotStack());
  std::string* addresses[] = {&stack->relocalization_, &stack->mapping_a_, &stack->mapping_b_};
  for (std::string* address : addresses) {
    absl::StatusOr<int> port = semnav::launcher::FreeLoopbackPort();
    if (!port.ok()) return port.status();
    *address = absl::StrCat("127.0.0.1:", *port);
  }
  semnav::launcher::StackConfig config;
  // Memory-only landmark maps: each run starts from nothing.
  config.services.push_back(
      {"relocalization", "semnav-relocalization", stack->relocalization_,
       WriteConfig(work_dir, "relocalization", kObjectMapRelocalizationYaml)});
  config.services.push_back(
      {"mapping_a", "semnav-mapping", stack->mapping_a_,
       WriteConfig(work_dir, "mapping_a",
                   MappingYaml(work_dir, "robot_a", stack->relocalization_))});
  config.services.push_back(
      {"mapping_b", "semnav-mapping", stack->mapping_b_,
       WriteConfig(work_dir, "mapping_b",
                   MappingYaml(work_dir, "robot_b", stack->relocalization_))});
  stack->runner_ = std::make_unique<semnav::launcher::StackRunner>(std::move(config), bin_dir);
  if (absl::Status s = stack->runner_->Start(); !s.ok()) return s;
  return stack;
}

TwoRobotStack::~TwoRobotStack() {
  if (runner_ != nullptr) runner_->Stop().IgnoreError();
}

TwoRobotEndpoints TwoRobotStack::endpoints() const {
  auto channel = [](const std::string& address) {
    return grpc::CreateChannel(address, grpc::InsecureChannelCredentials());
  };
  return TwoRobotEndpoints{channel(mapping_a_), channel(mapping_b_), channel(relocalization_)};
}

}  // namespace semnav::sim::loop
