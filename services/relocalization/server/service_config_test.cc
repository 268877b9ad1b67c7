#include "services/relocalization/server/service_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace semnav::relocalization {
namespace {

using ::testing::HasSubstr;

TEST(RelocServiceConfigTest, EmptySectionKeepsTheSeedDefaults) {
  ConfigReader empty = ConfigReader::Empty();
  const auto c = ServiceConfig::FromYaml(empty);
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_TRUE(c->storage_dir.empty());
  EXPECT_EQ(c->object_points.nms_kernel, 1);
  EXPECT_EQ(c->relocalization.match.early_stop_matches, 6u);
  EXPECT_DOUBLE_EQ(c->relocalization.match.similarity.alpha, 0.4);
  EXPECT_DOUBLE_EQ(c->relocalization.pose.outlier_distance_m, 0.2);
  EXPECT_EQ(c->relocalization.match.retrieval_labels, 3u);
  EXPECT_EQ(c->relocalization.max_hypotheses, 3);
  EXPECT_DOUBLE_EQ(c->relocalization.reliable_min_spread_m, 0.3);
  EXPECT_DOUBLE_EQ(c->relocalization.twin.radius_m, 1.0);
  EXPECT_DOUBLE_EQ(c->relocalization.twin.min_cosine, 0.95);
  EXPECT_TRUE(c->detector.model_path.empty());
}

TEST(RelocServiceConfigTest, ReadsNestedSections) {
  auto r = ConfigReader::FromString(
      "storage_dir: /tmp/maps\n"
      "matching: {early_stop_matches: 8, alpha: 0.5, retrieval_labels: 1}\n"
      "detector: {model_path: m.onnx, mean_rgb: [1, 2, 3]}\n"
      "reliability: {rotation_deg: 4, max_rms_m: 0.2, min_spread_m: 0}\n"
      "max_hypotheses: 1\n"
      "final_residual_gate_m: 0.5\n"
      "lookalike_twins: {radius_m: 0, min_cosine: 0.9, pose_tolerance_deg: 2}\n");
  ASSERT_TRUE(r.ok());
  const auto c = ServiceConfig::FromYaml(*r);
  ASSERT_TRUE(c.ok()) << c.status();
  EXPECT_EQ(c->storage_dir, "/tmp/maps");
  EXPECT_EQ(c->relocalization.match.early_stop_matches, 8u);
  EXPECT_DOUBLE_EQ(c->relocalization.match.similarity.alpha, 0.5);
  EXPECT_EQ(c->detector.model_path, "m.onnx");
  EXPECT_DOUBLE_EQ(c->detector.mean_b, 3.0);
  EXPECT_DOUBLE_EQ(c->relocalization.reliable_rotation_deg, 4.0);
  EXPECT_DOUBLE_EQ(c->relocalization.reliable_max_rms_m, 0.2);
  EXPECT_DOUBLE_EQ(c->relocalization.reliable_min_spread_m, 0.0);
  EXPECT_EQ(c->relocalization.max_hypotheses, 1);
  EXPECT_DOUBLE_EQ(c->relocalization.final_residual_gate_m, 0.5);
  EXPECT_EQ(c->relocalization.match.retrieval_labels, 1u);
  EXPECT_DOUBLE_EQ(c->relocalization.twin.radius_m, 0.0);
  EXPECT_DOUBLE_EQ(c->relocalization.twin.min_cosine, 0.9);
  EXPECT_DOUBLE_EQ(c->relocalization.twin.pose_tolerance_deg, 2.0);
  EXPECT_DOUBLE_EQ(c->relocalization.twin.pose_tolerance_m, 0.1);
}

TEST(RelocServiceConfigTest, BadValuesAndUnknownKeysNameTheKey) {
  auto r = ConfigReader::FromString(
      "pose: {min_inliers: 2}\nmatching: {bogus: 1}\nlookalike_twins: {min_cosine: 1.5}\n");
  ASSERT_TRUE(r.ok());
  const auto c = ServiceConfig::FromYaml(*r);
  EXPECT_EQ(c.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(c.status().message(), HasSubstr("pose.min_inliers"));
  EXPECT_THAT(c.status().message(), HasSubstr("matching.bogus"));
  EXPECT_THAT(c.status().message(), HasSubstr("lookalike_twins.min_cosine"));
}

}  // namespace
}  // namespace semnav::relocalization
