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
  config.reference = LocalizerReference::kTruth;
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

// Hand-checked with 1 m squares seen within 3 m: drift that the map was drawn with is no loss;
// coming back to a square drawn with another drift is.
TEST(SimLocalizerTest, MapReferenceAcceptsTheDriftTheMapWasDrawnWithAndCatchesARevisit) {
  LocalizerConfig config;
  config.enabled = true;
  config.latency_s = 2.0;
  SimLocalizer localizer(config);
  // Drawn at t = 0 with no drift: square (0, 0).
  EXPECT_EQ(localizer.Update(0.0, At(0.5, 0.5), At(0.5, 0.5)), api::LOCALIZATION_STATUS_OK);
  // 10 m on, the belief is 0.8 m ahead of the truth: a truth reference would say LOST, but no
  // square within 3 m is drawn, and then square (10, 0) is drawn with this drift.
  EXPECT_EQ(localizer.Update(1.0, At(10.8, 0.5), At(10.0, 0.5)), api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(4.0, At(10.8, 0.5), At(10.0, 0.5)), api::LOCALIZATION_STATUS_OK);
  EXPECT_NEAR(localizer.Expected(At(10.8, 0.5), At(10.0, 0.5)).position.x(), 10.8, 1e-12);
  // Back near square (0, 0) with the same 0.8 m: the nearest drawn square has no drift.
  EXPECT_EQ(localizer.Update(5.0, At(2.3, 0.5), At(1.5, 0.5)), api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(7.0, At(2.3, 0.5), At(1.5, 0.5)), api::LOCALIZATION_STATUS_LOST);
  EXPECT_NEAR(localizer.Expected(At(2.3, 0.5), At(1.5, 0.5)).position.x(), 1.5, 1e-12);
  // While lost nothing is drawn: with no drawn square in view the verdict stands.
  EXPECT_EQ(localizer.Update(8.0, At(20.5, 5.5), At(20.5, 5.5)), api::LOCALIZATION_STATUS_LOST);
  EXPECT_EQ(localizer.Update(11.0, At(20.5, 5.5), At(20.5, 5.5)), api::LOCALIZATION_STATUS_LOST);
  // A correction to where the map has the place: OK after the latency.
  EXPECT_EQ(localizer.Update(12.0, At(1.5, 0.5), At(1.5, 0.5)), api::LOCALIZATION_STATUS_LOST);
  EXPECT_EQ(localizer.Update(14.0, At(1.5, 0.5), At(1.5, 0.5)), api::LOCALIZATION_STATUS_OK);
}

TEST(SimLocalizerTest, MapReferenceCatchesAKidnapAndAcceptsTheRightCorrectionNearTheMap) {
  LocalizerConfig config;
  config.enabled = true;
  SimLocalizer localizer(config);
  // Not mapping (the gateway relocalizes): square (9, 9) is not drawn.
  EXPECT_EQ(localizer.Update(0.0, At(9.5, 9.5), At(9.5, 9.5), /*mapping=*/false),
            api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(1.0, At(0.5, 0.5), At(0.5, 0.5)), api::LOCALIZATION_STATUS_OK);
  // Carried 3 m without being told: the belief stays in square (0, 0).
  EXPECT_EQ(localizer.Update(2.0, At(0.5, 0.5), At(3.5, 0.5)), api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(4.0, At(0.5, 0.5), At(3.5, 0.5)), api::LOCALIZATION_STATUS_LOST);
  EXPECT_NEAR(localizer.Expected(At(0.5, 0.5), At(3.5, 0.5)).position.x(), 3.5, 1e-12);
  // The right correction puts the belief in square (3, 0), never drawn; square (0, 0), 3 m
  // away, agrees with it.
  EXPECT_EQ(localizer.Update(5.0, At(3.5, 0.5), At(3.5, 0.5)), api::LOCALIZATION_STATUS_LOST);
  EXPECT_EQ(localizer.Update(7.0, At(3.5, 0.5), At(3.5, 0.5)), api::LOCALIZATION_STATUS_OK);
  // Nothing drawn near square (9, 9): a wrong belief there is no evidence.
  EXPECT_EQ(localizer.Update(8.0, At(9.5, 9.5), At(3.5, 0.5)), api::LOCALIZATION_STATUS_OK);
  EXPECT_EQ(localizer.Update(11.0, At(9.5, 9.5), At(3.5, 0.5)), api::LOCALIZATION_STATUS_OK);
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
