#include "services/relocalization/core/pose_solver.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>
#include <random>

namespace semnav::relocalization {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

Eigen::Isometry3d MakePose(double yaw_deg, double pitch_deg, double roll_deg,
                           const Eigen::Vector3d& t) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(yaw_deg * kDeg, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(roll_deg * kDeg, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = t;
  return pose;
}

struct Pairs {
  std::vector<Eigen::Vector3d> p, q;
};

Pairs MakePairs(const Eigen::Isometry3d& map_from_query, int n, double noise, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  std::normal_distribution<double> e(0.0, noise);
  Pairs out;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p(u(rng), u(rng), 0.3 * u(rng));
    out.p.push_back(p);
    out.q.push_back(map_from_query * p + Eigen::Vector3d(e(rng), e(rng), e(rng)));
  }
  return out;
}

Eigen::Isometry3d Umeyama(const Pairs& pairs) {
  Eigen::Matrix3Xd src(3, pairs.p.size()), dst(3, pairs.q.size());
  for (size_t i = 0; i < pairs.p.size(); ++i) {
    src.col(static_cast<Eigen::Index>(i)) = pairs.p[i];
    dst.col(static_cast<Eigen::Index>(i)) = pairs.q[i];
  }
  return Eigen::Isometry3d(Eigen::umeyama(src, dst, false));
}

TEST(RelocPoseSolverTest, LevenbergMarquardtMatchesClosedFormUmeyama) {
  for (double yaw : {0.0, 35.0, 120.0, -170.0}) {
    const Pairs pairs = MakePairs(MakePose(yaw, -8.0, 5.0, {3.0, -2.0, 0.5}), 20, 0.03, 11);
    const auto est = SolvePose(pairs.p, pairs.q, PoseParams{});
    ASSERT_TRUE(est.ok()) << est.status();
    EXPECT_EQ(est->inliers.size(), 20u);
    const Eigen::Isometry3d closed_form = Umeyama(pairs);
    EXPECT_LT(RotationDifferenceDeg(est->map_from_query, closed_form), 1e-6) << "yaw " << yaw;
    EXPECT_LT(TranslationDifferenceM(est->map_from_query, closed_form), 1e-6) << "yaw " << yaw;
    EXPECT_NEAR(est->rms_residual_m, 0.03 * std::sqrt(3.0), 0.02);
  }
}

TEST(RelocPoseSolverTest, MedianDistanceRejectionRemovesPlantedOutliers) {
  const Eigen::Isometry3d truth = MakePose(60.0, 0.0, 0.0, {1.0, 2.0, 0.0});
  Pairs pairs = MakePairs(truth, 12, 0.02, 5);
  pairs.q[3] += Eigen::Vector3d(2.0, 0.0, 0.0);
  pairs.q[7] += Eigen::Vector3d(0.0, -3.0, 1.0);
  pairs.q[10] = pairs.q[0];  // a look-alike matched to another object
  const auto kept = RejectOutliersByMedianDistance(pairs.p, pairs.q, PoseParams{});
  EXPECT_EQ(kept, (std::vector<size_t>{0, 1, 2, 4, 5, 6, 8, 9, 11}));
  const auto est = SolvePose(pairs.p, pairs.q, PoseParams{});
  ASSERT_TRUE(est.ok());
  EXPECT_LT(TranslationDifferenceM(est->map_from_query, truth), 0.05);
  EXPECT_LT(RotationDifferenceDeg(est->map_from_query, truth), 1.0);
}

TEST(RelocPoseSolverTest, InconsistentPairsAreNotFound) {
  const Pairs a = MakePairs(Eigen::Isometry3d::Identity(), 4, 0.0, 1);
  const Pairs b = MakePairs(Eigen::Isometry3d::Identity(), 4, 0.0, 2);  // unrelated points
  const auto est = SolvePose(a.p, b.p, PoseParams{});
  EXPECT_EQ(est.status().code(), absl::StatusCode::kNotFound);
  EXPECT_NE(est.status().message().find("no consistent match"), absl::string_view::npos);
}

TEST(RelocPoseSolverTest, PoseDifferences) {
  const Eigen::Isometry3d a = MakePose(10.0, 0.0, 0.0, {1.0, 0.0, 0.0});
  const Eigen::Isometry3d b = MakePose(-20.0, 0.0, 0.0, {1.0, 4.0, 0.0});
  EXPECT_NEAR(RotationDifferenceDeg(a, b), 30.0, 1e-9);
  EXPECT_NEAR(TranslationDifferenceM(a, b), 4.0, 1e-12);
}

}  // namespace
}  // namespace semnav::relocalization
