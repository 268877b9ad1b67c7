#include "clients/sim/loop/localization_model.h"

#include <cmath>

#include "gtest/gtest.h"

namespace semnav::sim::loop {
namespace {

namespace api = semnav::reasoning::v1;

Pose At(double x, double y, double yaw = 0.0) { return Pose{Eigen::Vector3d(x, y, 0.0), yaw}; }

TEST(PoseAlgebraTest, ComposeAndInverseAreRigidTransforms) {
  const Pose a = At(1.0, 2.0, M_PI / 2);
  // Hand-checked: a quarter turn maps (1, 0) to (0, 1), then (1, 2) is added.
  const Pose moved = Compose(a, At(1.0, 0.0, 0.1));
  EXPECT_NEAR(moved.position.x(), 1.0, 1e-12);
  EXPECT_NEAR(moved.position.y(), 3.0, 1e-12);
  EXPECT_NEAR(moved.yaw, M_PI / 2 + 0.1, 1e-12);
  const Pose identity = Compose(Inverse(a), a);
  EXPECT_NEAR(identity.position.norm(), 0.0, 1e-12);
  EXPECT_NEAR(identity.yaw, 0.0, 1e-12);
  EXPECT_TRUE(IsIdentity(Pose{}));
}

TEST(SimLocalizerTest, ReportsLostOnlyAfterTheMismatchHeldForTheLatencyAndOkAfterAgreementHeld) {
  LocalizerConfig config;
  config.enabled = true;
  config.lost_distance_m = 0.5;
  config.latency_s = 2.0;
  SimLocalizer localizer(config);
  EXPECT_EQ(localizer.Update(0.0, At(0, 0), At(0.4, 0)),
            api::LOCALIZATION_STATUS_OK);  // within 0.5 m
  EXPECT_EQ(localizer.Update(1.0, At(0, 0), At(3, 0)),
            api::LOCALIZATION_STATUS_OK);  // mismatch from t = 1
  EXPECT_EQ(localizer.Update(2.5, At(0, 0), At(3, 0)), api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(3.0, At(0, 0), At(3, 0)), api::LOCALIZATION_STATUS_LOST);  // held 2 s
  EXPECT_EQ(localizer.Update(4.0, At(3, 0), At(3, 0)),
            api::LOCALIZATION_STATUS_LOST);  // agrees from t = 4
  EXPECT_EQ(localizer.Update(6.0, At(3, 0), At(3, 0)), api::LOCALIZATION_STATUS_OK);
  // A yaw mismatch alone counts too (15 deg default).
  EXPECT_EQ(localizer.Update(7.0, At(3, 0, 0.3), At(3, 0)), api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(9.0, At(3, 0, 0.3), At(3, 0)), api::LOCALIZATION_STATUS_LOST);
}

TEST(SimLocalizerTest, DisabledSaysNothing) {
  SimLocalizer localizer(LocalizerConfig{});
  EXPECT_EQ(localizer.Update(10.0, At(0, 0), At(50, 0)), api::LOCALIZATION_STATUS_UNSPECIFIED);
}

TEST(RecoveryTrackerTest, KidnapOpensALossTheNextCorrectionClosesItWithTimeAndError) {
  RecoveryTracker tracker;
  tracker.OnCorrection(1.0, At(0, 0), At(0, 0));  // no loss open: not a recovery
  tracker.OnKidnap(10.0);
  tracker.OnReport(12.0, api::LOCALIZATION_STATUS_LOST);  // the same loss
  tracker.OnCorrection(21.5, At(4.1, 0, 0.02), At(4.0, 0, 0.0));
  ASSERT_EQ(tracker.recoveries(), 1);
  EXPECT_EQ(tracker.losses(), 1);
  EXPECT_DOUBLE_EQ(tracker.times_s()[0], 11.5);
  EXPECT_NEAR(tracker.errors_m()[0], 0.1, 1e-12);
  EXPECT_NEAR(tracker.errors_deg()[0], 0.02 * 180.0 / M_PI, 1e-9);
  tracker.OnReport(30.0, api::LOCALIZATION_STATUS_LOST);  // a second loss, never recovered
  EXPECT_EQ(tracker.losses(), 2);
  EXPECT_EQ(tracker.recoveries(), 1);
}

TEST(ToTruthFrameTest, NavigateGoalPathAndHeadingMoveRotateDoesNot) {
  api::RobotCommand command;
  command.mutable_navigate()->mutable_goal()->set_x(1.0);
  command.mutable_navigate()->set_goal_yaw(0.5);
  command.mutable_navigate()->add_path()->mutable_position()->set_y(2.0);
  ToTruthFrame(command, At(10.0, 0.0, M_PI / 2));
  EXPECT_NEAR(command.navigate().goal().x(), 10.0, 1e-12);
  EXPECT_NEAR(command.navigate().goal().y(), 1.0, 1e-12);
  EXPECT_NEAR(command.navigate().goal_yaw(), 0.5 + M_PI / 2, 1e-12);
  EXPECT_NEAR(command.navigate().path(0).position().x(), 8.0, 1e-12);
  api::RobotCommand rotate;
  rotate.mutable_rotate()->set_angular_speed_rps(0.5);
  ToTruthFrame(rotate, At(10.0, 0.0, 1.0));
  EXPECT_DOUBLE_EQ(rotate.rotate().angular_speed_rps(), 0.5);
}

}  // namespace
}  // namespace semnav::sim::loop
