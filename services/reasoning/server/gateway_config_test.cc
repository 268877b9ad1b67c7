#include "services/reasoning/server/gateway_config.h"

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

// The config `yaml` gives, or the error it is rejected with; YAML that does not parse fails the
// test (every case here is well-formed YAML, judged by the gateway's own rules).
absl::StatusOr<GatewayConfig> Load(const std::string& yaml) {
  absl::StatusOr<ConfigReader> reader = ConfigReader::FromString(yaml);
  EXPECT_TRUE(reader.ok()) << yaml << ": " << reader.status();
  if (!reader.ok()) return reader.status();
  return GatewayConfig::FromYaml(*reader);
}

TEST(GatewayConfigTest, DefaultsAreTheSeedValues) {
  ConfigReader empty = ConfigReader::Empty();
  const absl::StatusOr<GatewayConfig> loaded = GatewayConfig::FromYaml(empty);
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const GatewayConfig& config = *loaded;
  EXPECT_DOUBLE_EQ(config.fast_path.label_weight, 0.35);
  EXPECT_DOUBLE_EQ(config.fast_path.embedding_weight, 0.35);
  EXPECT_DOUBLE_EQ(config.fast_path.detector_weight, 0.15);
  EXPECT_DOUBLE_EQ(config.fast_path.spatial_weight, 0.15);
  EXPECT_DOUBLE_EQ(config.fast_path.fast_threshold, 0.75);
  EXPECT_DOUBLE_EQ(config.slow_path.confidence_threshold, 0.6);
  EXPECT_DOUBLE_EQ(config.slow_path.vision_threshold, 0.5);
  EXPECT_DOUBLE_EQ(config.executor.approach_speed_mps, 0.15);
  EXPECT_DOUBLE_EQ(config.executor.look_around_rate_rps, 0.5);
  EXPECT_DOUBLE_EQ(config.executor.success_radius_m, 1.0);
  EXPECT_DOUBLE_EQ(config.executor.dependency_retry_s, 2.0);
  EXPECT_DOUBLE_EQ(config.executor.dependency_timeout_s, 60.0);
  EXPECT_DOUBLE_EQ(config.memory.node_spacing_m, 2.0);
  EXPECT_EQ(config.memory.max_nodes, 500);
  EXPECT_TRUE(config.mapping.address.empty());
  EXPECT_TRUE(config.planning.channel.address.empty());  // no planning: the robot plans locally
  EXPECT_EQ(config.planning.exploration_strategy, ExplorationStrategy::kSemanticFrontier);
  EXPECT_TRUE(config.model_proxy.channel.address.empty());  // offline default: no slow-path calls
  EXPECT_EQ(config.model_proxy.deadline_ms, 5000);
  EXPECT_EQ(config.model_proxy.max_in_flight, 2);
  EXPECT_FALSE(config.eroi.has_value());
  EXPECT_TRUE(
      absl::EndsWith(config.prior_path, "conceptnet_atlocation_coco80/conceptnet-data.json"));
}

TEST(GatewayConfigTest, ReadsTheModelProxyAndTheEroiVolumeAndNamesBadValues) {
  const absl::StatusOr<GatewayConfig> loaded = Load(
      "model_proxy: {address: 127.0.0.1:50054, deadline_ms: 800, vision_alias: vision}\n"
      "eroi: {min: [-10, -20, 0], nx: 9, ny: 19, nz: 2, theta: 4, evidence_once_per_code: "
      "false, inspect_distance_m: 4.5, sighting_namings: 1, failed_clues_to_geometric: 0}\n");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const GatewayConfig& config = *loaded;
  EXPECT_EQ(config.model_proxy.channel.address, "127.0.0.1:50054");
  EXPECT_EQ(config.model_proxy.deadline_ms, 800);
  EXPECT_EQ(config.model_proxy.vision_alias, "vision");
  ASSERT_TRUE(config.eroi.has_value());
  EXPECT_DOUBLE_EQ(config.eroi->grid.delta, 2.0);  // planning's default EROI edge
  EXPECT_DOUBLE_EQ(config.eroi->grid.min.y(), -20.0);
  EXPECT_EQ(config.eroi->grid.nz, 2);
  EXPECT_EQ(config.eroi->regions.theta, 4);
  EXPECT_FALSE(config.eroi->evidence_once_per_code);  // true by default
  EXPECT_DOUBLE_EQ(config.eroi->inspect_distance_m, 4.5);
  EXPECT_EQ(config.eroi->sighting_namings, 1);
  EXPECT_EQ(config.eroi->failed_clues_to_geometric, 0);  // 0 = the seed's search

  for (const char* yaml :
       {"model_proxy: {address: x, deadline_ms: 0}", "model_proxy: {address: x, max_in_flight: 64}",
        "eroi: {min: [0, 0]}", "eroi: {nx: 30}", "eroi: {theta: 0}",
        "eroi: {evidence_once_per_code: 3}", "eroi: {inspect_distance_m: .nan}",
        "eroi: {inspect_distance_m: -1}", "eroi: {sighting_namings: 0}",
        "eroi: {failed_clues_to_geometric: -1}", "eroi: {failed_clues_to_geometric: 1e9}"}) {
    const absl::Status status = Load(yaml).status();
    EXPECT_FALSE(status.ok()) << yaml;
    EXPECT_TRUE(absl::StrContains(status.message(), yaml[0] == 'm' ? "model_proxy." : "eroi."))
        << status;
  }
}

TEST(GatewayConfigTest, ReadsThePlanningClientAndRejectsUnknownStrategies) {
  const absl::StatusOr<GatewayConfig> loaded = Load(
      "planning: {address: 127.0.0.1:50052, exploration_strategy: EROI_UTILITY, deadline_ms: "
      "500, live_map_max_age_ms: 250}\n");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const GatewayConfig& config = *loaded;
  EXPECT_EQ(config.planning.channel.address, "127.0.0.1:50052");
  EXPECT_EQ(config.planning.exploration_strategy, ExplorationStrategy::kEroiUtility);
  EXPECT_EQ(config.planning.deadline_ms, 500);
  EXPECT_EQ(config.planning.live_map_max_age_ms, 250);
  EXPECT_EQ(PlanningSettings{}.live_map_max_age_ms, 500);

  const absl::Status status =
      Load("planning: {address: 127.0.0.1:50052, exploration_strategy: RANDOM}\n").status();
  EXPECT_FALSE(status.ok());
  EXPECT_TRUE(absl::StrContains(status.message(), "planning.exploration_strategy")) << status;

  const absl::Status too_old =
      Load("planning: {address: 127.0.0.1:50052, live_map_max_age_ms: 10001}\n").status();
  EXPECT_TRUE(absl::StrContains(too_old.message(), "planning.live_map_max_age_ms")) << too_old;

  const absl::StatusOr<GatewayConfig> detour = Load(
      "planning: {address: 127.0.0.1:50052, clearance_detour_factor: 2, clearance_detour_m: 5}\n");
  ASSERT_TRUE(detour.ok()) << detour.status();
  EXPECT_DOUBLE_EQ(detour->planning.clearance_detour_factor, 2.0);
  EXPECT_DOUBLE_EQ(detour->planning.clearance_detour_m, 5.0);
  for (const char* bad : {"clearance_detour_factor: 0.5", "clearance_detour_factor: .nan",
                          "clearance_detour_m: -1", "clearance_detour_m: 1e300"}) {
    const absl::Status refused =
        Load(absl::StrCat("planning: {address: 127.0.0.1:50052, ", bad, "}\n")).status();
    EXPECT_TRUE(absl::StrContains(refused.message(), "planning.clearance_detour")) << refused;
  }
}

TEST(GatewayConfigTest, ReadsValuesAndNamesBadKeys) {
  const absl::StatusOr<GatewayConfig> loaded = Load(
      "fast_path: {fast_threshold: 0.8}\n"
      "executor: {success_radius_m: 0.5, dependency_retry_s: 0.5, dependency_timeout_s: 5,\n"
      "           progress_timeout_s: 20, verify_view_m: 0.4, success_margin_m: 0.1, "
      "unreachable_region_m: 3,\n"
      "           time_budget_s: 250, endgame_s: 30, max_blocks_per_goal: 3,\n"
      "           explore_scan_duration_s: 6, start_scan_duration_s: 12.6,\n"
      "           explore_reselect_s: 3, explore_keep_radius_m: 1.5, verify_rule_out_misses: 5,\n"
      "           look_up_labels: [clock, tv], look_up_tilt_rad: 0.4, look_up_every_m: 6}\n"
      "mapping: {address: 127.0.0.1:50051}\n");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const GatewayConfig& config = *loaded;
  EXPECT_DOUBLE_EQ(config.fast_path.fast_threshold, 0.8);
  EXPECT_DOUBLE_EQ(config.executor.success_radius_m, 0.5);
  EXPECT_DOUBLE_EQ(config.executor.dependency_retry_s, 0.5);
  EXPECT_DOUBLE_EQ(config.executor.dependency_timeout_s, 5.0);
  EXPECT_DOUBLE_EQ(config.executor.progress_timeout_s, 20.0);
  EXPECT_DOUBLE_EQ(config.executor.verify_view_m, 0.4);
  EXPECT_DOUBLE_EQ(config.executor.success_margin_m, 0.1);
  EXPECT_DOUBLE_EQ(config.executor.unreachable_region_m, 3.0);
  EXPECT_DOUBLE_EQ(config.executor.time_budget_s, 250.0);
  EXPECT_DOUBLE_EQ(config.executor.endgame_s, 30.0);
  EXPECT_EQ(config.executor.max_blocks_per_goal, 3);
  EXPECT_DOUBLE_EQ(config.executor.explore_scan_duration_s, 6.0);
  EXPECT_DOUBLE_EQ(config.executor.start_scan_duration_s, 12.6);
  EXPECT_DOUBLE_EQ(config.executor.explore_reselect_s, 3.0);
  EXPECT_DOUBLE_EQ(config.executor.explore_keep_radius_m, 1.5);
  EXPECT_EQ(config.executor.verify_rule_out_misses, 5);
  EXPECT_EQ(config.executor.look_up_labels, (std::vector<std::string>{"clock", "tv"}));
  EXPECT_DOUBLE_EQ(config.executor.look_up_tilt_rad, 0.4);
  EXPECT_DOUBLE_EQ(config.executor.look_up_every_m, 6.0);
  EXPECT_EQ(config.mapping.address, "127.0.0.1:50051");

  for (const char* yaml : {"fast_path: {fast_threshold: 1.5}",
                           "executor: {success_radius_m: 0}",
                           "fast_path: {fast_treshold: 0.8}",
                           "executor: {dependency_retry_s: 0}",
                           "executor: {dependency_timeout_s: 1}",
                           "executor: {progress_timeout_s: 0}",
                           "executor: {success_margin_m: 1.0}",
                           "executor: {verify_view_m: 1.5}",
                           "executor: {time_budget_s: -1}",
                           "executor: {max_blocks_per_goal: 0}",
                           "executor: {look_around_after_blocks_at_spot: -1}",
                           "executor: {look_around_after_blocks_at_spot: 101}",
                           "executor: {max_contacts: -1}",
                           "executor: {max_contacts: 33}",
                           "executor: {explore_scan_duration_s: -1}",
                           "executor: {look_up_tilt_rad: 1.6}",
                           "executor: {look_up_tilt_rad: .nan}",
                           "executor: {look_up_every_m: -1}",
                           "executor: {explore_scan_duration_s: 121}",
                           "executor: {start_scan_duration_s: -0.5}",
                           "executor: {explore_reselect_s: -1}",
                           "executor: {explore_reselect_s: .nan}",
                           "executor: {explore_keep_radius_m: 51}",
                           "executor: {min_appearance_agreement: 1.5}",
                           "executor: {min_appearance_agreement: -0.1}",
                           "executor: {verify_rule_out_misses: -1}",
                           "executor: {verify_rule_out_misses: 1001}"}) {
    const absl::Status status = Load(yaml).status();
    EXPECT_FALSE(status.ok()) << yaml;
    EXPECT_TRUE(absl::StrContains(status.message(), yaml[0] == 'f' ? "fast_path." : "executor."))
        << status;
  }
}

TEST(GatewayConfigTest, ReadsTheJournalKeysAndBoundsTheFlushInterval) {
  const absl::StatusOr<GatewayConfig> loaded =
      Load("state_directory: /var/lib/semnav/gateway\njournal_flush_interval_s: 0.25\n");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const GatewayConfig& config = *loaded;
  EXPECT_EQ(config.state_directory, "/var/lib/semnav/gateway");
  EXPECT_DOUBLE_EQ(config.journal_flush_interval_s, 0.25);
  EXPECT_EQ(GatewayConfig{}.state_directory, "");  // memory only unless configured
  for (const char* yaml : {"journal_flush_interval_s: 0", "journal_flush_interval_s: 61"}) {
    EXPECT_TRUE(absl::StrContains(Load(yaml).status().message(), "journal_flush_interval_s"))
        << yaml;
  }
}

TEST(GatewayConfigTest, ReadsTheObjectConfirmationOfAGlobalMatchAndBoundsIt) {
  const RelocalizationLoopConfig defaults;
  EXPECT_EQ(defaults.confirm_min_objects, 2);
  EXPECT_DOUBLE_EQ(defaults.confirm_max_ray_conflicts, 0.15);
  const absl::StatusOr<GatewayConfig> loaded = Load(
      "relocalization:\n  address: 127.0.0.1:1\n  confirm_min_objects: 3\n"
      "  confirm_distance_m: 0.3\n  confirm_min_score: 0.5\n  confirm_min_cosine: 0.9\n"
      "  confirm_max_ray_conflicts: 0.15\n");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const RelocalizationLoopConfig& loop = loaded->relocalization.loop;
  EXPECT_EQ(loop.confirm_min_objects, 3);
  EXPECT_DOUBLE_EQ(loop.confirm_distance_m, 0.3);
  EXPECT_DOUBLE_EQ(loop.confirm_min_score, 0.5);
  EXPECT_DOUBLE_EQ(loop.confirm_min_cosine, 0.9);
  EXPECT_DOUBLE_EQ(loop.confirm_max_ray_conflicts, 0.15);
  for (const char* bad :
       {"confirm_min_objects: -1", "confirm_distance_m: .nan", "confirm_min_score: 1.5",
        "confirm_min_cosine: 2", "confirm_max_ray_conflicts: -0.1"}) {
    const absl::Status status =
        Load(std::string("relocalization:\n  address: 127.0.0.1:1\n  ") + bad + "\n").status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << bad;
    const std::string key(bad, std::string(bad).find(':'));
    EXPECT_TRUE(absl::StrContains(status.message(), key)) << status.message();
  }
}

TEST(GatewayConfigTest, ReadsHowManyFinishedTasksToKeepAndBoundsIt) {
  EXPECT_EQ(GatewayConfig{}.keep_finished_tasks, 256);
  const absl::StatusOr<GatewayConfig> loaded = Load("keep_finished_tasks: 0\n");
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  EXPECT_EQ(loaded->keep_finished_tasks, 0);
  for (const char* yaml : {"keep_finished_tasks: -1", "keep_finished_tasks: 100001"}) {
    EXPECT_TRUE(absl::StrContains(Load(yaml).status().message(), "keep_finished_tasks")) << yaml;
  }
}

}  // namespace
}  // namespace semnav::reasoning
