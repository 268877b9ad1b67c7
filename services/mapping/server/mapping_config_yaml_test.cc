#include "services/mapping/server/mapping_config_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace semnav::mapping {
namespace {

using ::testing::HasSubstr;

// The config `yaml` gives, or the error it is rejected with.
absl::StatusOr<MappingServiceConfig> Load(const std::string& yaml) {
  absl::StatusOr<ConfigReader> root = ConfigReader::FromString(yaml);
  if (!root.ok()) return root.status();
  ConfigReader section = root->Child("mapping");
  return MappingServiceConfig::FromYaml(section);
}

TEST(MappingConfigYamlTest, DefaultsFollowTheSeeds) {
  ConfigReader root = ConfigReader::Empty();
  ConfigReader section = root.Child("mapping");
  const absl::StatusOr<MappingServiceConfig> loaded = MappingServiceConfig::FromYaml(section);
  ASSERT_TRUE(loaded.ok()) << loaded.status();
  const MappingServiceConfig& config = *loaded;
  EXPECT_EQ(config.core.grid.p_threshold, 0.65);                // seed 003 eq. 9
  EXPECT_EQ(config.core.layers.obstacle_kernel, 9);             // seed 004
  EXPECT_EQ(config.core.lift.erosion_keep_above, 23.5);         // seed 004
  EXPECT_EQ(config.core.semantic.radius_m, 0.1f);               // seed 004
  EXPECT_EQ(config.core.scene.ema_new_weight, 0.3);             // seed 002
  EXPECT_EQ(config.core.scene.relations.region_radius_m, 3.0);  // seed 002
  EXPECT_EQ(config.core.range.min_m, 0.3);
  EXPECT_EQ(config.core.range.max_m, 8.0);
  EXPECT_EQ(config.core.heights.body_m, 0.0);        // seed 003's climbing
  EXPECT_EQ(config.occupancy_chunk_bytes, 1 << 20);  // DataChunk's protocol maximum
}

TEST(MappingConfigYamlTest, ChunkSizeStaysWithinTheProtocolLimit) {
  absl::StatusOr<ConfigReader> root =
      ConfigReader::FromString("mapping:\n  occupancy_chunk_bytes: 2097152\n");
  ASSERT_TRUE(root.ok());
  ConfigReader section = root->Child("mapping");
  const absl::Status status = MappingServiceConfig::FromYaml(section).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(status.message()), HasSubstr("mapping.occupancy_chunk_bytes"));
}

TEST(MappingConfigYamlTest, ReadsValuesAndNamesBadKeys) {
  absl::StatusOr<ConfigReader> root = ConfigReader::FromString(
      "mapping:\n  octomap: {resolution_m: 0.1}\n  synonyms: {sofa: [couch, settee]}\n");
  ASSERT_TRUE(root.ok());
  ConfigReader section = root->Child("mapping");
  const absl::StatusOr<MappingServiceConfig> config = MappingServiceConfig::FromYaml(section);
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->core.octomap_resolution_m, 0.1);
  EXPECT_EQ(config->core.synonyms.at("sofa"), (std::vector<std::string>{"couch", "settee"}));
  absl::StatusOr<ConfigReader> bad =
      ConfigReader::FromString("mapping:\n  grid: {p_threshold: 1.5}\n");
  ASSERT_TRUE(bad.ok());
  ConfigReader bad_section = bad->Child("mapping");
  const absl::Status status = MappingServiceConfig::FromYaml(bad_section).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(status.message()), HasSubstr("mapping.grid.p_threshold"));
}

TEST(MappingConfigYamlTest, SemanticPruningIsReadAndRangeChecked) {
  const absl::StatusOr<MappingServiceConfig> config = Load(
      "mapping:\n  semantic: {prune_growth: 3, prune_min_points: 100, "
      "instance_support_margin_m: -1}\n");
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->core.semantic.prune_growth, 3.0);
  EXPECT_EQ(config->core.semantic.prune_min_points, 100);
  EXPECT_EQ(config->core.semantic.instance_support_margin_m, -1.0);
  for (const char* bad : {"prune_growth: 1.0", "prune_growth: .nan", "prune_min_points: 0",
                          "instance_support_margin_m: .inf", "instance_support_margin_m: 11",
                          "instance_support_min_share: 1.5", "instance_support_min_share: .nan"}) {
    const absl::Status status = Load(std::string("mapping:\n  semantic: {") + bad + "}\n").status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(std::string(status.message()),
                HasSubstr(std::string("mapping.semantic.") +
                          std::string(bad).substr(0, std::string(bad).find(':'))))
        << bad;
  }
}

TEST(MappingConfigYamlTest, TheGlobalMatchsRayCheckIsReadAndRangeChecked) {
  absl::StatusOr<MappingServiceConfig> config =
      Load("mapping:\n  scan_match: {global_ray_emerge_cells: 0, global_max_ray_conflicts: 0.2}\n");
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->core.global_scan_match.ray_emerge_cells, 0);
  EXPECT_EQ(config->core.global_scan_match.max_ray_conflicts, 0.2);
  EXPECT_EQ(Load("mapping: {}\n")->core.global_scan_match.ray_emerge_cells, 3);  // the default
  for (const char* bad : {"global_ray_emerge_cells: 21", "global_ray_emerge_cells: -1"}) {
    const absl::Status status =
        Load(std::string("mapping:\n  scan_match: {") + bad + "}\n").status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(std::string(status.message()),
                HasSubstr("mapping.scan_match.global_ray_emerge_cells"))
        << bad;
  }
}

TEST(MappingConfigYamlTest, ExistenceIsReadAndRangeChecked) {
  const absl::StatusOr<MappingServiceConfig> config = Load(
      "mapping:\n  scene_graph: {existence: {max_range_m: 3, min_misses: 5, enabled: false}}\n");
  ASSERT_TRUE(config.ok()) << config.status();
  const ExistenceConfig& existence = config->core.scene.existence;
  EXPECT_EQ(existence.max_range_m, 3.0);
  EXPECT_EQ(existence.min_misses, 5);
  EXPECT_FALSE(existence.enabled);
  EXPECT_EQ(existence.max_misses_per_detection, 3.0);  // default kept
  for (const char* bad : {"max_range_m: .inf", "image_margin: 0.5", "min_misses: 0",
                          "max_misses_per_detection: .nan", "min_view_fraction: -1"}) {
    const absl::Status status =
        Load(std::string("mapping:\n  scene_graph: {existence: {") + bad + "}}\n").status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(std::string(status.message()), HasSubstr("mapping.scene_graph.existence.")) << bad;
  }
}

TEST(MappingConfigYamlTest, BodyHeightIsReadAndMustFitBetweenFootAndCeiling) {
  const absl::StatusOr<MappingServiceConfig> config =
      Load("mapping:\n  grid: {body_height_m: 0.5}\n");
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->core.heights.body_m, 0.5);
  // Defaults h_f 0.1, h_c 2.3: at most 2.2 m; negative is refused too.
  for (const char* bad :
       {"mapping:\n  grid: {body_height_m: 2.3}\n", "mapping:\n  grid: {body_height_m: -0.1}\n"}) {
    const absl::Status status = Load(bad).status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << bad;
    EXPECT_THAT(std::string(status.message()), HasSubstr("mapping.grid.body_height_m"));
  }
}

// Regression: a landmarks section without `relocalization` (or none at all, as in deploy/k8s)
// must not demand a relocalization address; mapping then pushes nothing.
TEST(MappingConfigYamlTest, LandmarksWithoutRelocalizationNeedNoAddress) {
  const absl::StatusOr<MappingServiceConfig> config = Load(
      "mapping:\n  landmarks: {min_detections: 5, labels: [chair, table], embedding_dim: 0}\n");
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->landmarks.min_detections, 5);
  EXPECT_EQ(config->landmarks.labels, (std::vector<std::string>{"chair", "table"}));
  EXPECT_EQ(config->landmarks.embedding_dim, 0);
  EXPECT_TRUE(config->landmark_publisher.relocalization.address.empty());
  EXPECT_EQ(config->landmark_publisher.live_map_id, "live");
  EXPECT_FALSE(config->landmark_publisher.push_with_frames);  // a real robot's frames never wait
}

TEST(MappingConfigYamlTest, TheLockStepSimulatorPushesLandmarksWithItsFrames) {
  const absl::StatusOr<MappingServiceConfig> config =
      Load("mapping:\n  landmarks: {push_with_frames: true}\n");
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_TRUE(config->landmark_publisher.push_with_frames);
  EXPECT_EQ(Load("mapping:\n  landmarks: {push_with_frames: 3.5}\n").status().code(),
            absl::StatusCode::kInvalidArgument);
}

TEST(MappingConfigYamlTest, LandmarkSettingsAreCheckedWithTheirKeyPath) {
  const absl::Status status =
      Load(
          "mapping:\n  landmarks: {live_map_id: '../x', relocalization: {address: "
          "'127.0.0.1:50053'}}\n")
          .status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(std::string(status.message()), HasSubstr("mapping.landmarks.live_map_id"));
}

TEST(MappingConfigYamlTest, IntegrationThreadsAndTheirPriorityAreReadAndBounded) {
  const absl::StatusOr<MappingServiceConfig> config =
      Load("mapping:\n  integration_threads: 3\n  integration_nice: 0\n");
  ASSERT_TRUE(config.ok()) << config.status();
  EXPECT_EQ(config->integration_threads, 3);
  EXPECT_EQ(config->integration_nice, 0);
  for (const auto& [yaml, key] : std::vector<std::pair<std::string, std::string>>{
           {"mapping:\n  integration_threads: 0\n", "mapping.integration_threads"},
           {"mapping:\n  integration_threads: 17\n", "mapping.integration_threads"},
           {"mapping:\n  integration_nice: -1\n", "mapping.integration_nice"},
           {"mapping:\n  integration_nice: 20\n", "mapping.integration_nice"}}) {
    const absl::Status status = Load(yaml).status();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << yaml;
    EXPECT_THAT(std::string(status.message()), HasSubstr(key));
  }
}

}  // namespace
}  // namespace semnav::mapping
