#include "services/reasoning/core/relocalization_loop.h"

#include <cmath>

#include "absl/strings/match.h"
#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

using Kind = RelocalizationAction::Kind;

std::vector<Kind> Kinds(const std::vector<RelocalizationAction>& actions) {
  std::vector<Kind> kinds;
  for (const RelocalizationAction& action : actions) kinds.push_back(action.kind);
  return kinds;
}

SceneObject Object(int64_t id, double x, double y, int detections) {
  SceneObject object;
  object.id = id;
  object.label = "chair";
  object.position = Eigen::Vector3d(x, y, 0.4);
  object.detection_count = detections;
  object.embedding = {1.0f, 0.0f};
  return object;
}

RobotPose Pose(double x, double y, double yaw = 0.0) {
  return RobotPose{Eigen::Vector3d(x, y, 0.0), yaw};
}

RelocalizationLoopConfig Config() {
  RelocalizationLoopConfig config;
  config.look_around_rate_rps = 0.5;
  config.look_around_duration_s = 12.0;
  config.query_interval_s = 0.0;  // the tests below query once, at the end of the turn
  config.answer_timeout_s = 5.0;
  config.min_observed_objects = 3;
  config.min_object_detections = 1;  // the tests below count on single detections
  config.max_attempts = 2;
  config.refine_with_scan = false;  // the refinement's own tests below turn it on
  return config;
}

// Before the loss the map has objects 1 and 2; the look-around finds 3, 4, 5 (new) and sees 1
// again.
SceneGraph Before() { return SceneGraph{1, {Object(1, 1, 0, 4), Object(2, 5, 0, 3)}, {}, {}}; }
SceneGraph After() {
  return SceneGraph{2,
                    {Object(1, 1, 0, 6), Object(2, 5, 0, 3), Object(3, 2, 2, 1),
                     Object(4, -1, 3, 2), Object(5, 0, -2, 1)},
                    {},
                    {}};
}

TEST(PlanarTransformTest, InverseUndoesApply) {
  const PlanarTransform t{Eigen::Vector3d(2.0, -1.0, 0.0), 0.7};
  const Eigen::Vector3d p(0.3, 4.0, 1.0);
  const Eigen::Vector3d back = t.Inverse().Apply(t.Apply(p));
  EXPECT_NEAR((back - p).norm(), 0.0, 1e-12);
  // Hand-checked: 90 deg turn then (1, 0) shift maps (1, 0) to (1, 1).
  const PlanarTransform quarter{Eigen::Vector3d(1.0, 0.0, 0.0), M_PI / 2};
  EXPECT_NEAR(quarter.Apply(Eigen::Vector3d(1, 0, 0)).x(), 1.0, 1e-12);
  EXPECT_NEAR(quarter.Apply(Eigen::Vector3d(1, 0, 0)).y(), 1.0, 1e-12);
  EXPECT_NEAR(quarter.Apply(Pose(0, 0, 0.5)).yaw, 0.5 + M_PI / 2, 1e-12);
}

TEST(RelocalizationLoopTest, LostReportPausesLooksAroundRelocalizesCorrectsAndResumes) {
  RelocalizationLoop loop(Config());
  EXPECT_TRUE(loop.OnState(0.0, Pose(0, 0), LocalizationReport::kOk, Before(), true).empty());
  // t = 1: the robot reports LOST.
  std::vector<RelocalizationAction> actions =
      loop.OnState(1.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kPauseTask, Kind::kCommand}));
  EXPECT_TRUE(absl::StrContains(actions[0].message, "LOST"));
  EXPECT_EQ(actions[1].command.kind, CommandKind::kRotate);
  EXPECT_DOUBLE_EQ(actions[1].command.angular_speed, 0.5);
  EXPECT_DOUBLE_EQ(actions[1].command.duration_s, 12.0);
  EXPECT_TRUE(loop.relocalizing());
  // Still LOST while turning: nothing new until the turn's 12 s are over.
  EXPECT_TRUE(loop.OnState(7.0, Pose(0, 0, 3.0), LocalizationReport::kLost, After(), true).empty());
  actions = loop.OnState(13.0, Pose(0, 0, 6.0), LocalizationReport::kLost, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kHold);
  // The three new objects only (object 1 was seen again but is not needed), nearest first.
  ASSERT_EQ(actions[1].observed.size(), 3u);
  EXPECT_EQ(actions[1].observed[0].object_id, 5);  // (0, -2): 2.0 m
  EXPECT_EQ(actions[1].observed[1].object_id, 3);  // (2, 2): 2.83 m
  EXPECT_EQ(actions[1].observed[2].object_id, 4);  // (-1, 3): 3.16 m
  EXPECT_DOUBLE_EQ(actions[1].observed[0].scale_m, Config().default_object_scale_m);
  // The answer: the odometry frame sits 3 m along +x, turned 90 deg, in the map.
  RelocalizationAnswer answer;
  answer.map_from_odom = PlanarTransform{Eigen::Vector3d(3.0, 0.0, 0.0), M_PI / 2};
  answer.reliable = true;
  answer.inliers = 3;
  actions = loop.OnAnswer(13.5, answer);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_NEAR(actions[0].map_from_odom.translation.x(), 3.0, 1e-12);
  EXPECT_FALSE(loop.relocalizing());
  EXPECT_TRUE(loop.trusted());
  EXPECT_EQ(loop.recoveries(), 1);
  // The robot's localizer takes a moment to agree: the same LOST report does not restart at once.
  EXPECT_TRUE(loop.OnState(14.0, Pose(0, 0), LocalizationReport::kLost, After(), true).empty());
  EXPECT_TRUE(loop.OnState(15.0, Pose(0, 0), LocalizationReport::kOk, After(), true).empty());
}

TEST(RelocalizationLoopTest, ObservedObjectsAreInTheOdometryFrameOfTheCurrentCorrection) {
  RelocalizationLoop loop(Config());
  loop.OnRequest(0.0, "", Before());
  RelocalizationAnswer answer;
  answer.map_from_odom = PlanarTransform{Eigen::Vector3d(10.0, 0.0, 0.0), 0.0};
  answer.reliable = true;
  loop.OnState(12.0, Pose(0, 0), LocalizationReport::kOk, After(), false);
  loop.OnAnswer(12.1, answer);
  // A second request: objects the mapping graph has at map x = 12 are at odometry x = 2.
  SceneGraph before{3, {}, {}, {}};
  loop.OnRequest(20.0, "check", before);
  SceneGraph after{4, {Object(7, 12, 0, 1), Object(8, 11, 1, 1), Object(9, 10, -1, 1)}, {}, {}};
  std::vector<RelocalizationAction> actions =
      loop.OnState(32.0, Pose(0, 0), LocalizationReport::kOk, after, false);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  EXPECT_NEAR(actions[1].observed[2].position.x(), 2.0, 1e-12);  // object 7, farthest
  EXPECT_NEAR(actions[1].observed[0].position.x(), 0.0, 1e-12);  // object 9
}

TEST(RelocalizationLoopTest, PoseJumpBeyondTopSpeedTriggersButFastMotionWithinItDoesNot) {
  RelocalizationLoop loop(Config());
  loop.SetLimits(1.0, 1.0);
  EXPECT_TRUE(loop.OnState(0.0, Pose(0, 0), LocalizationReport::kOk, Before(), true).empty());
  // 1.4 m in 0.5 s: top speed allows 0.5 m + 1.0 m jump margin.
  EXPECT_TRUE(loop.OnState(0.5, Pose(1.4, 0), LocalizationReport::kOk, Before(), true).empty());
  // 1.6 m in 0.5 s: beyond.
  std::vector<RelocalizationAction> actions =
      loop.OnState(1.0, Pose(3.0, 0), LocalizationReport::kOk, Before(), true);
  ASSERT_FALSE(actions.empty());
  EXPECT_EQ(actions[0].kind, Kind::kPauseTask);
  EXPECT_TRUE(absl::StrContains(actions[0].message, "jumped"));
}

TEST(RelocalizationLoopTest, YawJumpTriggersAndANewSessionIsNoJump) {
  RelocalizationLoop loop(Config());
  loop.SetLimits(1.0, 1.0);
  loop.OnState(0.0, Pose(0, 0, 0.0), LocalizationReport::kOk, Before(), false);
  loop.OnSessionOpened();
  EXPECT_TRUE(
      loop.OnState(0.1, Pose(20, 0, 3.0), LocalizationReport::kOk, Before(), false).empty());
  // 0.1 s: 0.1 rad allowed + 0.6 rad margin; 1.0 rad is a jump.
  EXPECT_FALSE(
      loop.OnState(0.2, Pose(20, 0, 2.0), LocalizationReport::kOk, Before(), false).empty());
}

TEST(RelocalizationLoopTest, TooFewObjectsRetriesThenFailsTheTaskAndLeavesThePoseUntrusted) {
  RelocalizationLoop loop(Config());
  loop.OnState(0.0, Pose(0, 0), LocalizationReport::kUncertain, Before(), true);
  // The first turn saw nothing new: a second look-around.
  std::vector<RelocalizationAction> actions =
      loop.OnState(12.0, Pose(0, 0), LocalizationReport::kUncertain, Before(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kRotate);
  EXPECT_TRUE(absl::StrContains(actions[0].command.reason, "attempt 2"));
  actions = loop.OnState(24.0, Pose(0, 0), LocalizationReport::kUncertain, Before(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kFailTask}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kStop);
  EXPECT_TRUE(absl::StrContains(actions[1].message, "saw 0 objects, 3 needed"));
  EXPECT_TRUE(absl::StrContains(actions[1].message, "UNCERTAIN"));
  EXPECT_FALSE(loop.trusted());
  EXPECT_EQ(loop.failures(), 1);
  // Idle on an untrusted pose: nothing; a new task on it relocalizes first.
  EXPECT_TRUE(
      loop.OnState(25.0, Pose(0, 0), LocalizationReport::kUncertain, Before(), false).empty());
  actions = loop.OnState(26.0, Pose(0, 0), LocalizationReport::kOk, Before(), true);
  ASSERT_FALSE(actions.empty());
  EXPECT_TRUE(absl::StrContains(actions[0].message, "untrusted"));
}

TEST(RelocalizationLoopTest, UnreliableAnswerRetriesAndATimeoutFailsInTheRobotsClock) {
  RelocalizationLoop loop(Config());
  loop.OnRequest(0.0, "drifted", Before());
  ASSERT_EQ(Kinds(loop.OnState(12.0, Pose(0, 0), LocalizationReport::kOk, After(), true)),
            (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  RelocalizationAnswer unreliable;
  unreliable.reliable = false;
  unreliable.inliers = 2;
  std::vector<RelocalizationAction> actions = loop.OnAnswer(12.2, unreliable);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kRotate);
  // The second turn sees the first turn's objects once more: they count (the baseline stayed).
  actions = loop.OnState(24.2, Pose(0, 0), LocalizationReport::kOk, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  // No answer within 5 s of the robot's clock: the task fails; a late answer changes nothing.
  EXPECT_TRUE(loop.OnState(29.0, Pose(0, 0), LocalizationReport::kOk, After(), true).empty());
  actions = loop.OnState(29.3, Pose(0, 0), LocalizationReport::kOk, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kFailTask}));
  EXPECT_TRUE(absl::StrContains(actions[1].message, "did not answer within 5.0 s"));
  RelocalizationAnswer late;
  late.reliable = true;
  EXPECT_TRUE(loop.OnAnswer(30.0, late).empty());
  EXPECT_EQ(loop.recoveries(), 0);
}

TEST(RelocalizationLoopTest, OperatorRequestWhileRelocalizingChangesNothing) {
  RelocalizationLoop loop(Config());
  ASSERT_FALSE(loop.OnRequest(0.0, "", Before()).empty());
  EXPECT_EQ(loop.trigger(), "operator request");
  EXPECT_TRUE(loop.OnRequest(1.0, "again", Before()).empty());
  EXPECT_EQ(loop.trigger(), "operator request");
}

TEST(RelocalizationLoopTest, ServiceErrorIsARetryThenTheTaskFailsNamingIt) {
  RelocalizationLoopConfig config = Config();
  config.max_attempts = 1;
  RelocalizationLoop loop(config);
  loop.OnState(0.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, After(), true);
  std::vector<RelocalizationAction> actions =
      loop.OnAnswer(12.1, absl::NotFoundError("too few landmarks in map 'kitchen'"));
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kFailTask}));
  EXPECT_TRUE(absl::StrContains(actions[1].message, "too few landmarks in map 'kitchen'"));
}

// The kidnapped bench group's look-arounds (mission.md, "Losing the pose"): objects detected once
// during the turn were mostly ghosts far from any object of their label, so by default an object
// needs two detections in the turn, and a re-seen object two more than before it.
TEST(RelocalizationLoopTest, ObjectsDetectedOnceDuringTheLookAroundStayOut) {
  RelocalizationLoopConfig config = Config();
  config.min_object_detections = RelocalizationLoopConfig{}.min_object_detections;
  ASSERT_EQ(config.min_object_detections, 2);
  RelocalizationLoop loop(config);
  loop.OnState(0.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  // Object 1 seen once more (4 -> 5), object 2 twice more (3 -> 5); new: 3 (once), 4 (twice),
  // 5 (once), 6 (three times).
  const SceneGraph after{2,
                         {Object(1, 1, 0, 5), Object(2, 5, 0, 5), Object(3, 2, 2, 1),
                          Object(4, -1, 3, 2), Object(5, 0, -2, 1), Object(6, 0, 4, 3)},
                         {},
                         {}};
  const std::vector<RelocalizationAction> actions =
      loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, after, true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  // New first (4 at 3.16 m, 6 at 4 m), then the re-seen object 2; 3, 5 and 1 stay out.
  ASSERT_EQ(actions[1].observed.size(), 3u);
  EXPECT_EQ(actions[1].observed[0].object_id, 4);
  EXPECT_EQ(actions[1].observed[1].object_id, 6);
  EXPECT_EQ(actions[1].observed[2].object_id, 2);
  EXPECT_EQ(actions[1].observed[2].observations, 2);
}

// Too few objects seen twice is a failed attempt, not a call with ghosts.
TEST(RelocalizationLoopTest, SingleDetectionsDoNotMakeUpTheMinimum) {
  RelocalizationLoopConfig config = Config();
  config.min_object_detections = 2;
  RelocalizationLoop loop(config);
  loop.OnState(0.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  // After(): new 3 (once), 4 (twice), 5 (once); 1 seen twice more: 2 objects qualify.
  const std::vector<RelocalizationAction> actions =
      loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kRotate);  // the second attempt's turn
}

// Mapping's live landmark map already holds the look-around's objects when the query arrives, so
// relocalization can answer the robot's believed pose back with a perfect fit. While the robot
// reports LOST that answer is a failed attempt; once the robot reports OK, a small one is fine.
TEST(RelocalizationLoopTest, AnAnswerConfirmingTheLostPoseIsNoRecovery) {
  RelocalizationLoop loop(Config());
  loop.OnState(0.0, Pose(2, 1, 0.3), LocalizationReport::kLost, Before(), true);
  std::vector<RelocalizationAction> actions =
      loop.OnState(12.0, Pose(2, 1, 0.3), LocalizationReport::kLost, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  RelocalizationAnswer self;  // 0.05 m, 0.5 deg: the pose the robot believes, back again
  self.map_from_odom = PlanarTransform{Eigen::Vector3d(0.05, 0.0, 0.0), 0.5 * M_PI / 180.0};
  self.reliable = true;
  self.inliers = 4;
  actions = loop.OnAnswer(12.5, self);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand}));  // the second turn
  EXPECT_EQ(actions[0].command.kind, CommandKind::kRotate);
  EXPECT_EQ(loop.recoveries(), 0);
  EXPECT_TRUE(loop.relocalizing());
  // Second attempt, the same answer: the task fails with the reason, the pose stays untrusted.
  actions = loop.OnState(25.0, Pose(2, 1, 0.3), LocalizationReport::kLost, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRelocalize}));
  actions = loop.OnAnswer(25.5, self);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kFailTask}));
  EXPECT_TRUE(absl::StrContains(actions[1].message, "confirms the pose the robot reports LOST"));
  EXPECT_FALSE(loop.trusted());
  // An operator's check on a robot reporting OK may confirm its pose.
  loop.OnState(30.0, Pose(2, 1, 0.3), LocalizationReport::kOk, Before(), false);
  loop.OnRequest(31.0, "check", Before());
  loop.OnState(43.0, Pose(2, 1, 0.3), LocalizationReport::kOk, After(), false);
  actions = loop.OnAnswer(43.5, self);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(loop.trusted());
}

// The kidnapped target is an answer within 15 s of the kidnap, and the localizer reports LOST
// 2.5 s after it (mission.md, "Losing the pose"): the turn runs at 0.75 rad/s by default (8.4 s
// for a full turn), capped by the robot's own yaw rate, and the objects go to relocalization as
// they come in; a reliable answer ends the turn there.
TEST(RelocalizationLoopTest, QueriesDuringTheTurnAndAReliableAnswerEndsItEarly) {
  RelocalizationLoopConfig config;  // the defaults
  config.min_object_detections = 1;
  RelocalizationLoop loop(config);
  std::vector<RelocalizationAction> actions =
      loop.OnState(0.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kPauseTask, Kind::kCommand}));
  EXPECT_DOUBLE_EQ(actions[1].command.angular_speed, 0.75);
  EXPECT_NEAR(actions[1].command.duration_s, 8.4, 1e-12);
  // 0.5 s: too early for a query (interval 1 s); 1.0 s: only two objects are new, too few.
  EXPECT_TRUE(loop.OnState(0.5, Pose(0, 0, 0.5), LocalizationReport::kLost, After(), true).empty());
  const SceneGraph two{2, {Object(1, 1, 0, 4), Object(3, 2, 2, 1), Object(4, -1, 3, 2)}, {}, {}};
  EXPECT_TRUE(loop.OnState(1.0, Pose(0, 0, 1.0), LocalizationReport::kLost, two, true).empty());
  // 1.5 s: three new objects; asked while the turn goes on (no hold).
  actions = loop.OnState(1.5, Pose(0, 0, 1.5), LocalizationReport::kLost, After(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kRelocalize}));
  EXPECT_EQ(actions[0].observed.size(), 3u);
  // Waiting for that answer: no second call.
  EXPECT_TRUE(loop.OnState(2.0, Pose(0, 0, 2.0), LocalizationReport::kLost, After(), true).empty());
  // Not reliable: the turn goes on, and the same three objects are not asked about again.
  RelocalizationAnswer unreliable;
  unreliable.inliers = 2;
  EXPECT_TRUE(loop.OnAnswer(2.0, unreliable).empty());
  EXPECT_TRUE(loop.relocalizing());
  EXPECT_TRUE(loop.OnState(2.5, Pose(0, 0, 2.5), LocalizationReport::kLost, After(), true).empty());
  // 3.0 s: a fourth object: the next query; its reliable answer stops the turn and resumes.
  SceneGraph more = After();
  more.objects.push_back(Object(6, 3, -3, 2));
  actions = loop.OnState(3.0, Pose(0, 0, 3.0), LocalizationReport::kLost, more, true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kRelocalize}));
  EXPECT_EQ(actions[0].observed.size(), 4u);
  RelocalizationAnswer answer;
  answer.map_from_odom = PlanarTransform{Eigen::Vector3d(1.5, -2.0, 0.0), 0.4};
  answer.reliable = true;
  answer.inliers = 4;
  actions = loop.OnAnswer(3.5, answer);
  // The turn stops; by default the answer goes to the scan matcher first (its tests below).
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kRefine}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kHold);
  EXPECT_TRUE(loop.relocalizing());
  actions = loop.OnRefinement(4.0, absl::UnavailableError("mapping is down"));
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_FALSE(loop.relocalizing());
  EXPECT_EQ(loop.recoveries(), 1);
  EXPECT_NEAR(loop.map_from_odom().yaw, 0.4, 1e-12);
}

// A robot whose hello says it turns at most 0.4 rad/s turns the same full circle more slowly.
TEST(RelocalizationLoopTest, TheTurnKeepsItsAngleAtTheRobotsLowerYawRate) {
  RelocalizationLoop loop(RelocalizationLoopConfig{});
  loop.SetLimits(0.5, 0.4);
  const std::vector<RelocalizationAction> actions = loop.OnRequest(0.0, "", Before());
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kPauseTask, Kind::kCommand}));
  EXPECT_DOUBLE_EQ(actions[1].command.angular_speed, 0.4);
  EXPECT_NEAR(actions[1].command.duration_s, 8.4 * 0.75 / 0.4, 1e-9);  // 15.75 s
}

}  // namespace
}  // namespace semnav::reasoning

namespace semnav::reasoning {
namespace {

RelocalizationAnswer Reliable(double x, double y, double yaw) {
  RelocalizationAnswer answer;
  answer.map_from_odom = PlanarTransform{Eigen::Vector3d(x, y, 0.0), yaw};
  answer.reliable = true;
  answer.inliers = 4;
  return answer;
}

// Operator request, a full turn, the answer: returns the actions that follow the answer.
std::vector<RelocalizationAction> RelocalizeOnce(RelocalizationLoop& loop, double start,
                                                 const RelocalizationAnswer& answer) {
  loop.OnRequest(start, "", Before());
  loop.OnState(start + 12.0, Pose(0, 0), LocalizationReport::kOk, After(), false);
  return loop.OnAnswer(start + 12.1, answer);
}

RelocalizationLoopConfig RefiningConfig() {
  RelocalizationLoopConfig config = Config();
  config.refine_with_scan = true;
  return config;
}

// The coarse answer goes to the scan matcher in the frame the robot's sensor frames carry (the
// current correction applied to odometry), and the refined correction comes back to odometry.
TEST(RelocalizationLoopScanRefinementTest, TheAnswerIsRefinedInTheRobotsReportedFrame) {
  RelocalizationLoop loop(RefiningConfig());
  // First recovery: the refinement keeps the answer, so the correction is (10, 0, 0 deg).
  std::vector<RelocalizationAction> actions = RelocalizeOnce(loop, 0.0, Reliable(10, 0, 0));
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kRefine}));
  EXPECT_TRUE(loop.relocalizing());  // no motion until the refinement answers
  ScanRefinement kept;
  kept.map_from_reported = actions[0].map_from_odom;
  kept.refined = false;
  kept.score = 0.2;
  actions = loop.OnRefinement(12.5, kept);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(absl::StrContains(actions[0].message, "kept the answer (score 0.20"))
      << actions[0].message;
  EXPECT_NEAR(loop.map_from_odom().translation.x(), 10.0, 1e-12);
  EXPECT_FALSE(loop.relocalizing());

  // Second: the answer puts odometry at (0, 10) turned 90 deg. Reported = (10, 0, 0) * odometry,
  // so the matcher gets answer * (10, 0, 0)^-1: p -> R90 (p - (10, 0)) + (0, 10), which takes
  // (10, 0) to (0, 10) and turns by 90 deg: translation (0, 10) - R90 (10, 0) = (0, 0).
  actions = RelocalizeOnce(loop, 20.0, Reliable(0, 10, M_PI / 2));
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kRefine}));
  EXPECT_NEAR(actions[0].map_from_odom.translation.x(), 0.0, 1e-12);
  EXPECT_NEAR(actions[0].map_from_odom.translation.y(), 0.0, 1e-12);
  EXPECT_NEAR(actions[0].map_from_odom.yaw, M_PI / 2, 1e-12);
  // The walls move it 0.1 m along x and 2 deg: map_from_odom = refined * (10, 0, 0).
  ScanRefinement refined;
  refined.map_from_reported = PlanarTransform{Eigen::Vector3d(0.1, 0.0, 0.0), M_PI / 2 + 0.035};
  refined.refined = true;
  refined.score = 0.8;
  refined.coarse_score = 0.5;
  actions = loop.OnRefinement(32.5, refined);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(absl::StrContains(actions[0].message, "scan-refined")) << actions[0].message;
  EXPECT_TRUE(absl::StrContains(actions[0].message, "score 0.50 -> 0.80")) << actions[0].message;
  // (10, 0) in reported terms -> R(92 deg) (10, 0) + (0.1, 0).
  const double yaw = M_PI / 2 + 0.035;
  EXPECT_NEAR(loop.map_from_odom().translation.x(), 10.0 * std::cos(yaw) + 0.1, 1e-9);
  EXPECT_NEAR(loop.map_from_odom().translation.y(), 10.0 * std::sin(yaw), 1e-9);
  EXPECT_NEAR(loop.map_from_odom().yaw, yaw, 1e-12);
  EXPECT_EQ(loop.recoveries(), 2);
  // A late second refinement answer changes nothing.
  EXPECT_TRUE(loop.OnRefinement(33.0, refined).empty());
}

TEST(RelocalizationLoopScanRefinementTest, AFailedOrSilentMatcherLeavesTheCoarseAnswer) {
  RelocalizationLoop failed(RefiningConfig());
  ASSERT_EQ(Kinds(RelocalizeOnce(failed, 0.0, Reliable(3, 1, 0.2))),
            (std::vector<Kind>{Kind::kRefine}));
  std::vector<RelocalizationAction> actions =
      failed.OnRefinement(12.3, absl::NotFoundError("no untrusted frame"));
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(absl::StrContains(actions[0].message, "scan refinement failed: no untrusted frame"));
  EXPECT_NEAR(failed.map_from_odom().translation.x(), 3.0, 1e-12);
  EXPECT_NEAR(failed.map_from_odom().yaw, 0.2, 1e-12);

  // No answer within answer_timeout_s (5 s) of the robot's clock: the coarse answer applies.
  RelocalizationLoop silent(RefiningConfig());
  RelocalizeOnce(silent, 0.0, Reliable(3, 1, 0.2));
  EXPECT_TRUE(silent.OnState(17.0, Pose(0, 0), LocalizationReport::kOk, After(), false).empty());
  actions = silent.OnState(17.2, Pose(0, 0), LocalizationReport::kOk, After(), false);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(absl::StrContains(actions[0].message, "did not answer within 5.0 s"));
  EXPECT_FALSE(silent.relocalizing());
  EXPECT_NEAR(silent.map_from_odom().translation.y(), 1.0, 1e-12);
}

// A turn that sees too few objects asks for the whole-map scan match before the attempt fails:
// a unique match recovers the robot, none lets the next attempt start with the reason kept.
TEST(RelocalizationLoopScanRefinementTest, TooFewObjectsAskForAGlobalScanMatchFirst) {
  RelocalizationLoop loop(RefiningConfig());
  loop.OnRequest(0.0, "", Before());
  // The turn ends having seen nothing new.
  std::vector<RelocalizationAction> actions =
      loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kRefine}));
  EXPECT_TRUE(actions[0].global);
  EXPECT_TRUE(absl::StrContains(actions[0].message, "saw 0 objects")) << actions[0].message;
  EXPECT_TRUE(loop.relocalizing());
  // Not unique: the second look-around starts, and its failure would name both reasons.
  ScanRefinement ambiguous;
  ambiguous.refined = false;
  ambiguous.score = 0.8;
  ambiguous.runner_up_score = 0.79;
  actions = loop.OnRefinement(12.5, ambiguous);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kRotate);
  EXPECT_EQ(loop.recoveries(), 0);
  // The second turn sees nothing either; this time the match is unique: (4, -1) turned 30 deg
  // from the reported frame, which is odometry (no correction yet).
  actions = loop.OnState(25.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kRefine}));
  ScanRefinement unique;
  unique.map_from_reported = PlanarTransform{Eigen::Vector3d(4.0, -1.0, 0.0), M_PI / 6};
  unique.refined = true;
  unique.score = 0.85;
  unique.runner_up_score = 0.5;
  actions = loop.OnRefinement(25.5, unique);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(absl::StrContains(actions[0].message,
                                "global scan match (score 0.85, the best "
                                "other pose 0.50)"))
      << actions[0].message;
  EXPECT_NEAR(loop.map_from_odom().translation.x(), 4.0, 1e-12);
  EXPECT_NEAR(loop.map_from_odom().yaw, M_PI / 6, 1e-12);
  EXPECT_TRUE(loop.trusted());
  EXPECT_EQ(loop.recoveries(), 1);
}

TEST(RelocalizationLoopScanRefinementTest, ANonUniqueGlobalMatchOnTheLastAttemptFailsTheTask) {
  RelocalizationLoopConfig config = RefiningConfig();
  config.max_attempts = 1;
  RelocalizationLoop loop(config);
  loop.OnRequest(0.0, "", Before());
  loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, Before(), true);
  ScanRefinement ambiguous;
  ambiguous.score = 0.7;
  ambiguous.runner_up_score = 0.69;
  // Its best pose: the robot (at the odometry origin, no correction yet) at (2, 1), turned a
  // quarter; the reason names it.
  ambiguous.map_from_reported = PlanarTransform{Eigen::Vector3d(2.0, 1.0, 0.0), M_PI / 2};
  const std::vector<RelocalizationAction> actions = loop.OnRefinement(12.5, ambiguous);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand, Kind::kFailTask}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kStop);
  EXPECT_TRUE(absl::StrContains(actions[1].message,
                                "saw 0 objects, 3 needed; no unique global "
                                "scan match (score 0.70 at (2.00, 1.00, 90 deg), the best other "
                                "pose 0.69, rays through walls 0 %)"))
      << actions[1].message;
  EXPECT_FALSE(loop.trusted());
}

// The robot believes it stands 10 m east of where it does. Its turn finds two chairs, at (11, 0)
// and (15, 0) in the frame it believes: too few for relocalization, so the whole map is
// scan-matched. The best pose (10 m west) scores below min_score, but it puts both chairs on the
// map's chairs 1 and 2.
SceneGraph TurnFinds(const std::vector<SceneObject>& found) {
  SceneGraph graph = Before();
  graph.revision = 2;
  graph.objects.insert(graph.objects.end(), found.begin(), found.end());
  return graph;
}

std::vector<RelocalizationAction> GlobalAnswer(RelocalizationLoop& loop, const SceneGraph& turn,
                                               double score, double ray_conflicts,
                                               double west_m = 10.0) {
  loop.OnRequest(0.0, "", Before());
  const std::vector<RelocalizationAction> asked =
      loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, turn, true);
  EXPECT_EQ(Kinds(asked), (std::vector<Kind>{Kind::kRefine}));
  EXPECT_TRUE(!asked.empty() && asked[0].global);
  ScanRefinement refused;
  refused.refined = false;
  refused.map_from_reported = PlanarTransform{Eigen::Vector3d(-west_m, 0.0, 0.0), 0.0};
  refused.score = score;
  refused.runner_up_score = 0.4;
  refused.ray_conflicts = ray_conflicts;
  return loop.OnRefinement(12.5, refused);
}

TEST(RelocalizationLoopScanRefinementTest, ObjectsTheTurnFoundConfirmARefusedGlobalMatch) {
  const SceneGraph turn = TurnFinds({Object(3, 11, 0, 2), Object(4, 15, 0, 2)});
  RelocalizationLoop loop(RefiningConfig());
  std::vector<RelocalizationAction> actions = GlobalAnswer(loop, turn, 0.5, 0.1);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  EXPECT_TRUE(absl::StrContains(actions[0].message,
                                "global scan match confirmed by 2 objects (score 0.50, the best "
                                "other pose 0.40, rays through walls 10 %) after: the look-around "
                                "saw 2 objects, 3 needed"))
      << actions[0].message;
  EXPECT_NEAR(loop.map_from_odom().translation.x(), -10.0, 1e-12);
  EXPECT_TRUE(loop.trusted());

  // Each bound refuses it: too many rays through walls, too low a score, only one chair within
  // 0.5 m (the pose 10.4 m west puts them 0.4 m off: still two; 10.6 m: none), a chair that
  // looks different, and the rule turned off.
  const auto refused = [](const std::vector<RelocalizationAction>& a) {
    return Kinds(a) == std::vector<Kind>{Kind::kCommand} &&
           a[0].command.kind == CommandKind::kRotate;
  };
  RelocalizationLoop walls(RefiningConfig());
  EXPECT_TRUE(refused(GlobalAnswer(walls, turn, 0.5, 0.16)));
  RelocalizationLoop low(RefiningConfig());
  EXPECT_TRUE(refused(GlobalAnswer(low, turn, 0.44, 0.1)));
  RelocalizationLoop near(RefiningConfig());
  EXPECT_EQ(Kinds(GlobalAnswer(near, turn, 0.5, 0.1, 10.4)),
            (std::vector<Kind>{Kind::kCorrect, Kind::kResumeTask}));
  RelocalizationLoop off_by(RefiningConfig());
  EXPECT_TRUE(refused(GlobalAnswer(off_by, turn, 0.5, 0.1, 10.6)));
  SceneObject other = Object(4, 15, 0, 2);
  other.embedding = {0.0f, 1.0f};
  RelocalizationLoop looks_different(RefiningConfig());
  EXPECT_TRUE(
      refused(GlobalAnswer(looks_different, TurnFinds({Object(3, 11, 0, 2), other}), 0.5, 0.1)));
  RelocalizationLoopConfig off = RefiningConfig();
  off.confirm_min_objects = 0;
  RelocalizationLoop without(off);
  EXPECT_TRUE(refused(GlobalAnswer(without, turn, 0.5, 0.1)));
}

// One object of the turn confirms one map object: two map chairs 0.3 m apart under one found
// chair are one confirmation, and objects already on the map before the loss confirm nothing.
TEST(RelocalizationLoopScanRefinementTest, EachFoundObjectConfirmsOneMapObject) {
  SceneGraph before{1, {Object(1, 1, 0, 4), Object(2, 1.3, 0, 3)}, {}, {}};
  SceneGraph turn = before;
  turn.objects.push_back(Object(3, 11.1, 0, 2));
  turn.objects[0].detection_count = 9;  // seen again in the turn, but on the map before
  RelocalizationLoop loop(RefiningConfig());
  loop.OnRequest(0.0, "", before);
  ASSERT_EQ(Kinds(loop.OnState(12.0, Pose(0, 0), LocalizationReport::kLost, turn, true)),
            (std::vector<Kind>{Kind::kRefine}));
  ScanRefinement refused;
  refused.map_from_reported = PlanarTransform{Eigen::Vector3d(-10.0, 0.0, 0.0), 0.0};
  refused.score = 0.55;
  const std::vector<RelocalizationAction> actions = loop.OnRefinement(12.5, refused);
  ASSERT_EQ(Kinds(actions), (std::vector<Kind>{Kind::kCommand}));
  EXPECT_EQ(actions[0].command.kind, CommandKind::kRotate);
  EXPECT_EQ(loop.recoveries(), 0);
}

}  // namespace
}  // namespace semnav::reasoning
