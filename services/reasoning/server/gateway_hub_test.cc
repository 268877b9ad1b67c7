// The hub without gRPC: a fake session sink records the robot commands.
#include "services/reasoning/server/gateway_hub.h"

#include <cmath>
#include <limits>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "gtest/gtest.h"
#include "services/common/status/field_error.h"
#include "services/reasoning/core/robot_local_planner.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

api::SubmitInstructionRequest SubmitRequest(const std::string& request_id,
                                            const std::string& robot_id,
                                            const std::string& instruction) {
  api::SubmitInstructionRequest request;
  request.set_request_id(request_id);
  request.set_robot_id(robot_id);
  request.set_instruction(instruction);
  return request;
}

TEST(GatewayHubTest, BacktrackReturnsToWhereTheSofaWasSeen) {
  RobotLocalPlanner planner;
  const GatewayConfig config;
  GatewayHub hub(config, &ShippedLexicon(), &planner);
  hub.OnSceneGraph(SofaScene());

  RecordingSink session;
  api::SessionHello hello;
  hello.set_robot_id("r1");
  ASSERT_TRUE(hub.OpenSession(hello, &session).ok());
  ASSERT_TRUE(hub.OnRobotState(&session, At(0, 0)).ok());   // node 1 sees the sofa (1.1 m away)
  ASSERT_TRUE(hub.OnRobotState(&session, At(6, 0)).ok());   // node 2, 5 m from the sofa: not seen
  ASSERT_TRUE(hub.OnRobotState(&session, At(12, 0)).ok());  // node 3

  absl::StatusOr<api::SubmitInstructionResponse> response =
      hub.Submit(SubmitRequest("back-1", "r1", "回到沙发那里"));
  ASSERT_TRUE(response.ok()) << response.status();
  ASSERT_EQ(response->task().subgoals(0).type(), api::SUBGOAL_TYPE_BACKTRACK);
  ASSERT_GE(session.messages().size(), 2u);  // accepted + navigate
  const api::RobotCommand command = session.Last();
  ASSERT_TRUE(command.has_navigate()) << command.ShortDebugString();
  EXPECT_DOUBLE_EQ(command.navigate().goal().x(), 0.0);
  EXPECT_DOUBLE_EQ(command.navigate().goal().y(), 0.0);
  EXPECT_EQ(command.navigate().path_size(), 0);  // no planning service: robot plans locally
  hub.Shutdown();
  ASSERT_TRUE(session.closed().has_value());
  EXPECT_EQ(session.closed()->error_code(), grpc::StatusCode::UNAVAILABLE);
}

// Planning gone as a task starts: the robot holds and the log names planning at once (the
// task's first snapshot is already PAUSED, which no status change would report).
TEST(GatewayHubTest, TaskThatStartsWhilePlanningIsGoneHoldsAndLogsIt) {
  class GonePlanner : public PathPlanner {
   public:
    absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery&) override {
      return DependencyUnavailableError("planning", "PlanPath: not connected");
    }
    absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery&) override {
      return DependencyUnavailableError("planning", "SelectExplorationGoal: not connected");
    }
  } planner;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
  RecordingSink session;
  api::SessionHello hello;
  hello.set_robot_id("r1");
  ASSERT_TRUE(hub.OpenSession(hello, &session).ok());
  ASSERT_TRUE(hub.OnRobotState(&session, At(0, 0)).ok());
  absl::StatusOr<api::SubmitInstructionResponse> response =
      hub.Submit(SubmitRequest("find-1", "r1", "find the red cup"));
  ASSERT_TRUE(response.ok()) << response.status();
  const api::RobotCommand command = session.Last();
  EXPECT_TRUE(command.has_hold()) << command.ShortDebugString();
  EXPECT_EQ(response->task().status(), api::TASK_STATUS_PAUSED);
  api::ListEventsRequest request;
  request.set_task_id(response->task_id());
  const api::ListEventsResponse listed = *hub.ListEvents(request);
  ASSERT_GE(listed.events_size(), 2) << listed.DebugString();
  EXPECT_EQ(listed.events(listed.events_size() - 1).message(),
            "TASK_STATUS_PAUSED: dependency_unavailable: planning "
            "(planning unavailable: SelectExplorationGoal: not connected)");
  hub.Shutdown();
}

// Planning's exploration picks its rule by the platform: the hello's modes decide it.
TEST(GatewayHubTest, ExplorationTellsPlanningWhetherTheRobotFlies) {
  class RecordingPlanner : public PathPlanner {
   public:
    absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override {
      return std::vector<Eigen::Vector3d>{query.goal};
    }
    absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) override {
      platforms.push_back(query.platform);
      return query.pose.position + Eigen::Vector3d(3.0, 0.0, 0.0);
    }
    std::vector<RobotPlatform> platforms;
  };
  struct Case {
    std::vector<api::LocomotionMode> modes;
    RobotPlatform expected;
  };
  const std::vector<Case> cases = {
      {{}, RobotPlatform::kGround},  // an empty list means GROUND only
      {{api::LOCOMOTION_MODE_GROUND}, RobotPlatform::kGround},
      {{api::LOCOMOTION_MODE_AIR}, RobotPlatform::kAerial},
      {{api::LOCOMOTION_MODE_GROUND, api::LOCOMOTION_MODE_FLY_ROLL}, RobotPlatform::kAerial},
  };
  for (const Case& c : cases) {
    RecordingPlanner planner;
    GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
    RecordingSink session;
    api::SessionHello hello;
    hello.set_robot_id("r1");
    for (api::LocomotionMode mode : c.modes) hello.mutable_capabilities()->add_modes(mode);
    ASSERT_TRUE(hub.OpenSession(hello, &session).ok());
    ASSERT_TRUE(hub.OnRobotState(&session, At(0, 0)).ok());
    ASSERT_TRUE(hub.Submit(SubmitRequest("find-1", "r1", "find the red cup")).ok());
    ASSERT_FALSE(planner.platforms.empty()) << hello.ShortDebugString();
    EXPECT_EQ(planner.platforms.back(), c.expected) << hello.ShortDebugString();
    hub.Shutdown();
  }
}

// operator.proto: control of a finished task is FAILED_PRECONDITION naming task_id, but a retry
// of the call that finished it (same request_id) gets that call's answer again.
TEST(GatewayHubTest, ControlOfAFinishedTaskIsRefusedButARetryGetsTheFirstAnswer) {
  RobotLocalPlanner planner;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
  absl::StatusOr<api::SubmitInstructionResponse> submitted =
      hub.Submit(SubmitRequest("s-1", "r1", "wait"));
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  api::CancelTaskRequest cancel;
  cancel.set_request_id("c-1");
  cancel.set_task_id(submitted->task_id());
  absl::StatusOr<api::TaskSnapshot> cancelled = hub.Cancel(cancel);
  ASSERT_TRUE(cancelled.ok()) << cancelled.status();
  EXPECT_EQ(cancelled->status(), api::TASK_STATUS_CANCELLED);

  absl::StatusOr<api::TaskSnapshot> retried = hub.Cancel(cancel);
  ASSERT_TRUE(retried.ok()) << retried.status();
  EXPECT_EQ(retried->SerializeAsString(), cancelled->SerializeAsString());

  cancel.set_request_id("c-2");
  const absl::Status again = hub.Cancel(cancel).status();
  EXPECT_EQ(again.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_EQ(again.message(), "task_id: task task-1 already finished (TASK_STATUS_CANCELLED)");
  api::PauseTaskRequest pause;
  pause.set_request_id("p-1");
  pause.set_task_id(submitted->task_id());
  EXPECT_EQ(hub.Pause(pause).status().code(), absl::StatusCode::kFailedPrecondition);
  api::ResumeTaskRequest resume;
  resume.set_request_id("r-1");
  resume.set_task_id(submitted->task_id());
  EXPECT_EQ(hub.Resume(resume).status().code(), absl::StatusCode::kFailedPrecondition);
}

TEST(GatewayHubTest, LeaseErrorsNameTheFieldOnce) {
  RobotLocalPlanner planner;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
  api::AcquireLeaseRequest acquire;
  acquire.set_request_id("l-1");
  acquire.set_robot_id("r2");
  acquire.set_holder("alice");
  ASSERT_TRUE(hub.AcquireLease(acquire).ok());
  acquire.set_request_id("l-2");
  acquire.set_holder("bob");
  const absl::Status held = hub.AcquireLease(acquire).status();
  EXPECT_EQ(held.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_TRUE(absl::StartsWith(held.message(), "robot_id: lease of r2 is held by alice until "))
      << held.message();

  const absl::Status refused = hub.Submit(SubmitRequest("s-1", "r2", "wait")).status();
  EXPECT_EQ(refused.message(), "lease_id: robot r2 is leased by alice");
}

// operator.proto ListEvents: a finished task's recorded events from its first (event 1, which
// StreamEvents cannot replay) without other tasks', and the log's newest id to stream on from.
TEST(GatewayHubTest, ListEventsGivesAFinishedTasksEventsAndTheNewestId) {
  RobotLocalPlanner planner;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner);
  absl::StatusOr<api::SubmitInstructionResponse> first =
      hub.Submit(SubmitRequest("s-1", "r1", "wait"));
  ASSERT_TRUE(first.ok()) << first.status();
  api::CancelTaskRequest cancel;
  cancel.set_request_id("c-1");
  cancel.set_task_id(first->task_id());
  cancel.set_reason("changed my mind");
  ASSERT_TRUE(hub.Cancel(cancel).ok());
  absl::StatusOr<api::SubmitInstructionResponse> second =
      hub.Submit(SubmitRequest("s-2", "r2", "wait"));
  ASSERT_TRUE(second.ok()) << second.status();

  api::ListEventsRequest request;
  request.set_task_id(first->task_id());
  const api::ListEventsResponse listed = *hub.ListEvents(request);
  ASSERT_GE(listed.events_size(), 2) << listed.DebugString();
  EXPECT_FALSE(listed.truncated());
  EXPECT_EQ(listed.events(0).event_id(), 1u);
  EXPECT_EQ(listed.events(0).kind(), api::EVENT_KIND_TASK_CREATED);
  EXPECT_EQ(listed.events(0).message(), "wait");
  const api::Event& last = listed.events(listed.events_size() - 1);
  EXPECT_EQ(last.kind(), api::EVENT_KIND_TASK_STATUS);
  EXPECT_EQ(last.message(), "TASK_STATUS_CANCELLED: changed my mind");
  for (const api::Event& event : listed.events()) EXPECT_EQ(event.task_id(), first->task_id());

  const api::ListEventsResponse everything = *hub.ListEvents(api::ListEventsRequest{});
  ASSERT_GT(everything.events_size(), listed.events_size());
  const api::Event& newest = everything.events(everything.events_size() - 1);
  EXPECT_EQ(newest.task_id(), second->task_id());
  EXPECT_EQ(listed.last_event_id(), newest.event_id());  // the whole log's, not the task's
  EXPECT_EQ(everything.last_event_id(), newest.event_id());

  request.set_task_id("");
  request.set_robot_id("r2");
  request.set_after_event_id(0);
  const api::ListEventsResponse of_r2 = *hub.ListEvents(request);
  ASSERT_GT(of_r2.events_size(), 0);
  for (const api::Event& event : of_r2.events()) EXPECT_EQ(event.task_id(), second->task_id());
  request.set_robot_id("");
  request.set_after_event_id(newest.event_id());
  EXPECT_EQ(hub.ListEvents(request)->events_size(), 0);
  // Like every operator request, its ids stay within kMaxIdBytes.
  request.set_task_id(std::string(1 << 20, 't'));
  const absl::StatusOr<api::ListEventsResponse> refused = hub.ListEvents(request);
  EXPECT_EQ(refused.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(refused.status()), "task_id");
  EXPECT_LT(refused.status().message().size(), 200u);
}

// A task whose creation is still retained lost no events, however much older ones were dropped.
TEST(GatewayHubTest, ListEventsIsTruncatedOnlyWhenTheTasksOwnEventsWereDropped) {
  RobotLocalPlanner planner;
  GatewayConfig config;
  config.retained_events = 3;
  GatewayHub hub(config, &ShippedLexicon(), &planner);
  std::vector<std::string> task_ids;
  for (const char* robot : {"r1", "r2", "r3"}) {
    absl::StatusOr<api::SubmitInstructionResponse> submitted =
        hub.Submit(SubmitRequest(absl::StrCat("s-", robot), robot, "wait"));
    ASSERT_TRUE(submitted.ok()) << submitted.status();
    task_ids.push_back(submitted->task_id());
    api::CancelTaskRequest cancel;
    cancel.set_request_id(absl::StrCat("c-", robot));
    cancel.set_task_id(submitted->task_id());
    ASSERT_TRUE(hub.Cancel(cancel).ok());
  }
  EXPECT_TRUE(hub.ListEvents(api::ListEventsRequest{})->truncated());
  api::ListEventsRequest request;
  request.set_task_id(task_ids.front());
  EXPECT_TRUE(hub.ListEvents(request)->truncated());
  request.set_task_id(task_ids.back());
  const api::ListEventsResponse last = *hub.ListEvents(request);
  EXPECT_FALSE(last.truncated()) << last.DebugString();
  ASSERT_GE(last.events_size(), 2);
  EXPECT_EQ(last.events(0).kind(), api::EVENT_KIND_TASK_CREATED);
}

}  // namespace
}  // namespace semnav::reasoning

namespace semnav::reasoning {
namespace {

class GatewayHubValidationTest : public ::testing::Test {
 protected:
  RobotLocalPlanner planner_;
  GatewayHub hub_{GatewayConfig{}, &ShippedLexicon(), &planner_};
};

// 400 Chinese characters are 1200 bytes: within the documented 1000 characters (the old check
// counted bytes and refused them).
TEST_F(GatewayHubValidationTest, InstructionLimitCountsCharacters) {
  std::string text;
  for (int i = 0; i < 50; ++i) text += "去厨房找红色杯子";
  api::DecomposeInstructionRequest request;
  request.set_instruction(text);
  EXPECT_TRUE(hub_.Decompose(request).ok()) << hub_.Decompose(request).status();
  for (int i = 0; i < 76; ++i) request.mutable_instruction()->append("去厨房找红色杯子");  // 1008
  absl::Status refused = hub_.Decompose(request).status();
  EXPECT_EQ(refused.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(refused), "instruction");
}

// Each request names its bad field, quotes at most a short prefix, and stores nothing.
TEST_F(GatewayHubValidationTest, BadFieldsAreNamedAndNothingIsStored) {
  const std::string huge(1 << 20, 'x');
  absl::Status task = hub_.GetTask(huge).status();
  EXPECT_EQ(ErrorField(task), "task_id");
  EXPECT_LT(task.message().size(), 200u);

  api::AcquireLeaseRequest lease;
  lease.set_request_id("lease-1");
  lease.set_robot_id("r1");
  lease.set_holder(huge);
  EXPECT_EQ(ErrorField(hub_.AcquireLease(lease).status()), "holder");
  lease.set_holder("alice");
  lease.mutable_ttl()->set_seconds(std::numeric_limits<int64_t>::max());  // overflowed to ms
  EXPECT_EQ(ErrorField(hub_.AcquireLease(lease).status()), "ttl");

  api::CancelTaskRequest cancel;
  cancel.set_request_id("cancel-1");
  cancel.set_task_id("task-1");
  cancel.set_reason(huge);
  EXPECT_EQ(ErrorField(hub_.Cancel(cancel).status()), "reason");

  api::ResolveTargetRequest resolve;
  resolve.set_robot_id("r1");
  resolve.mutable_target()->set_name("cup");
  for (int i = 0; i < 1000; ++i) resolve.mutable_target()->add_colours("red");
  EXPECT_EQ(ErrorField(hub_.ResolveTarget(resolve).status()), "target.colours");

  api::ListTasksRequest list;
  list.set_robot_id(huge);
  EXPECT_EQ(ErrorField(hub_.ListTasks(list).status()), "robot_id");

  api::SubmitInstructionRequest submit = SubmitRequest("req-1", huge, "find the cup");
  EXPECT_EQ(ErrorField(hub_.Submit(submit).status()), "robot_id");
  EXPECT_EQ(hub_.ListTasks({})->tasks_size(), 0);
}

// Both lease calls take a ttl between 1 s and max_lease_ttl_s (600 s); without one a lease runs
// default_lease_ttl_s (30 s).
TEST_F(GatewayHubValidationTest, LeaseTimesStayWithinTheConfiguredRange) {
  api::AcquireLeaseRequest acquire;
  acquire.set_request_id("lease-ttl-1");
  acquire.set_robot_id("r1");
  acquire.set_holder("alice");
  acquire.mutable_ttl()->set_nanos(500'000'000);  // 0.5 s
  EXPECT_EQ(ErrorField(hub_.AcquireLease(acquire).status()), "ttl");
  acquire.set_request_id("lease-ttl-2");
  acquire.mutable_ttl()->set_nanos(0);
  acquire.mutable_ttl()->set_seconds(601);
  EXPECT_EQ(ErrorField(hub_.AcquireLease(acquire).status()), "ttl");
  acquire.set_request_id("lease-ttl-3");
  acquire.clear_ttl();
  absl::StatusOr<api::Lease> lease = hub_.AcquireLease(acquire);
  ASSERT_TRUE(lease.ok()) << lease.status();

  api::RenewLeaseRequest renew;
  renew.set_lease_id(lease->lease_id());
  renew.mutable_ttl()->set_nanos(500'000'000);
  EXPECT_EQ(ErrorField(hub_.RenewLease(renew).status()), "ttl");
  renew.mutable_ttl()->set_nanos(0);
  renew.mutable_ttl()->set_seconds(600);
  EXPECT_TRUE(hub_.RenewLease(renew).ok());
}

// A hello with a NaN capability opens no session; a camera frame with a NaN pose is refused
// (the session logs and skips it) before anything reads it.
TEST_F(GatewayHubValidationTest, HelloAndCameraFramesAreChecked) {
  RecordingSink session;
  api::SessionHello hello;
  hello.set_robot_id("r1");
  hello.mutable_capabilities()->set_max_linear_speed_mps(std::nan(""));
  EXPECT_EQ(ErrorField(hub_.OpenSession(hello, &session).status()),
            "hello.capabilities.max_linear_speed_mps");
  EXPECT_TRUE(session.messages().empty());  // not accepted
  hello.mutable_capabilities()->set_max_linear_speed_mps(1.0);
  hello.mutable_capabilities()->add_modes(static_cast<api::LocomotionMode>(42));
  EXPECT_EQ(ErrorField(hub_.OpenSession(hello, &session).status()), "hello.capabilities.modes[0]");
  hello.mutable_capabilities()->clear_modes();
  for (double tilt : {std::nan(""), -0.1, 2.0, 1e300}) {  // a camera tilts up by at most pi/2
    hello.mutable_capabilities()->set_camera_tilt_max_rad(tilt);
    EXPECT_EQ(ErrorField(hub_.OpenSession(hello, &session).status()),
              "hello.capabilities.camera_tilt_max_rad");
  }
  EXPECT_TRUE(session.messages().empty());
  hello.mutable_capabilities()->set_camera_tilt_max_rad(0.6);
  ASSERT_TRUE(hub_.OpenSession(hello, &session).ok());

  api::CameraFrame frame;
  frame.mutable_camera_pose()->mutable_position()->set_x(std::nan(""));
  EXPECT_EQ(ErrorField(hub_.OnCameraFrame(&session, frame)), "camera.camera_pose.position.x");
  hub_.CloseSession(&session);
}

// A NaN robot state is refused naming the coordinate; the pose stays the last good one, so the
// task's first step is planned from it.
TEST_F(GatewayHubValidationTest, NonFiniteRobotStateIsRefusedAndThePoseKept) {
  RecordingSink session;
  api::SessionHello hello;
  hello.set_robot_id("r1");
  ASSERT_TRUE(hub_.OpenSession(hello, &session).ok());
  ASSERT_TRUE(hub_.OnRobotState(&session, At(2, 0)).ok());
  api::RobotState lost = At(0, 0);
  lost.mutable_pose()->mutable_position()->set_y(std::nan(""));
  absl::Status refused = hub_.OnRobotState(&session, lost);
  EXPECT_EQ(refused.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(ErrorField(refused), "state.pose.position.y");
  api::RobotState fast = At(1e6, 0);
  EXPECT_EQ(ErrorField(hub_.OnRobotState(&session, fast)), "state.pose.position.x");
  api::RobotState spinning = At(0, 0);
  spinning.mutable_velocity()->set_z(INFINITY);
  EXPECT_EQ(ErrorField(hub_.OnRobotState(&session, spinning)), "state.velocity.z");

  ASSERT_TRUE(hub_.Submit(SubmitRequest("req-1", "r1", "find the bottle")).ok());
  // No map: the first step is 3 m east of the last good pose (2, 0).
  const api::RobotCommand first = session.Last();
  ASSERT_TRUE(first.has_navigate());
  EXPECT_DOUBLE_EQ(first.navigate().goal().x(), 5.0);
  EXPECT_DOUBLE_EQ(first.navigate().goal().y(), 0.0);
  hub_.CloseSession(&session);  // the sink dies before the hub
}

}  // namespace
}  // namespace semnav::reasoning
