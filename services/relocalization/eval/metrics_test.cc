#include "services/relocalization/eval/metrics.h"

#include <gtest/gtest.h>

#include <numbers>

namespace semnav::relocalization::eval {
namespace {

TEST(RelocMetricsTest, PoseErrorPerAxisAndAngle) {
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d estimate = Eigen::Isometry3d::Identity();
  estimate.translation() = Eigen::Vector3d(0.3, -0.4, 0.0);
  estimate.linear() = Eigen::AngleAxisd(2.0 * std::numbers::pi / 180.0, Eigen::Vector3d::UnitX())
                          .toRotationMatrix();
  const PoseError e = ComputePoseError(estimate, truth);
  EXPECT_DOUBLE_EQ(e.ex, 0.3);
  EXPECT_DOUBLE_EQ(e.ey, 0.4);
  EXPECT_DOUBLE_EQ(e.ez, 0.0);
  EXPECT_NEAR(e.ep, 0.5, 1e-12);
  EXPECT_NEAR(e.er, 2.0, 1e-9);
}

TEST(RelocMetricsTest, RecallCountsOnlyAnswersWithinBounds) {
  std::vector<KeyframeOutcome> outcomes(4);
  outcomes[0] = {true, {0.01, 0, 0, 0.01, 0.1}, 1.0, 0.5};
  outcomes[1] = {true, {0.03, 0, 0, 0.03, 0.3}, 2.0, 1.0};
  outcomes[2] = {true, {0.9, 0, 0, 0.9, 0.3}, 3.0, 1.5};  // answered, but wrong
  outcomes[3] = {false, {}, 10.0, 2.0};                   // no answer
  const MethodSummary s = Summarize(outcomes, SuccessBounds{});
  EXPECT_DOUBLE_EQ(s.recall, 0.5);
  EXPECT_DOUBLE_EQ(s.answered_rate, 0.75);
  EXPECT_DOUBLE_EQ(s.median_pos_err_m, 0.01);  // nearest-rank median of {0.01, 0.03}
  EXPECT_DOUBLE_EQ(s.median_rot_err_deg, 0.1);
  EXPECT_DOUBLE_EQ(s.ms_median, 2.0);  // of {1, 2, 3, 10}
  EXPECT_DOUBLE_EQ(s.ms_p99, 10.0);
  EXPECT_DOUBLE_EQ(s.cpu_ms_median, 1.0);
}

}  // namespace
}  // namespace semnav::relocalization::eval
