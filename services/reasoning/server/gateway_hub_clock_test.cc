// Simulated-clock (lock-step) sessions: the robot's state stamps are its task's clock, every state
// is answered with StepDone after the commands it caused, step inputs wait for their state, and a
// model answer is used only once simulated time has covered the latency the model reported.
#include <atomic>
#include <thread>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "absl/time/clock.h"
#include "gtest/gtest.h"
#include "services/reasoning/core/robot_local_planner.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

api::RobotState StepState(double x, double y, double stamp_s, uint64_t step) {
  api::RobotState state = At(x, y);
  state.mutable_header()->mutable_stamp()->set_seconds(static_cast<int64_t>(stamp_s));
  state.mutable_header()->mutable_stamp()->set_nanos(
      static_cast<int32_t>((stamp_s - static_cast<int64_t>(stamp_s)) * 1e9));
  state.set_step(step);
  return state;
}

api::SessionHello SimulatedHello(const std::string& robot_id) {
  api::SessionHello hello;
  hello.set_robot_id(robot_id);
  hello.set_clock(api::CLOCK_KIND_SIMULATED);
  return hello;
}

api::SubmitInstructionRequest SubmitRequest(const std::string& instruction) {
  api::SubmitInstructionRequest request;
  request.set_request_id(instruction);
  request.set_robot_id("r1");
  request.set_instruction(instruction);
  return request;
}

// Indices of the session's messages that are commands, and of StepDone messages.
std::vector<std::size_t> CommandIndices(const std::vector<api::ConnectResponse>& messages) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < messages.size(); ++i) {
    if (messages[i].has_command()) out.push_back(i);
  }
  return out;
}

// A backtrack task to where the sofa was seen, submitted at simulated t = 3 s with the robot 12 m
// away: a navigate command whose 5 s timeout runs on the state stamps.
class SimulatedClockTest : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.executor.navigate_timeout_s = 5.0;
    hub_ = std::make_unique<GatewayHub>(config_, &ShippedLexicon(), &planner_);
    hub_->OnSceneGraph(SofaScene());
    ASSERT_TRUE(hub_->OpenSession(SimulatedHello("r1"), &session_).ok());
    ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(0, 0, 1.0, 1)).ok());
    ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(6, 0, 2.0, 2)).ok());
    ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(12, 0, 3.0, 3)).ok());
    absl::StatusOr<api::SubmitInstructionResponse> response =
        hub_->Submit(SubmitRequest("回到沙发那里"));
    ASSERT_TRUE(response.ok()) << response.status();
    task_id_ = response->task_id();
  }
  void TearDown() override { hub_->Shutdown(); }

  GatewayConfig config_;
  RobotLocalPlanner planner_;
  std::unique_ptr<GatewayHub> hub_;
  RecordingSink session_;
  std::string task_id_;
};

TEST_F(SimulatedClockTest, StateStampsDriveTheTaskClockNotTheWallClock) {
  ASSERT_TRUE(session_.Last().has_navigate());
  // 4 s of simulated time after the command: within its 5 s.
  ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(12, 0, 7.0, 4)).ok());
  EXPECT_EQ(hub_->GetTask(task_id_)->replans(), 0);
  // 5.5 s: timed out and re-planned, though only milliseconds of wall time have passed.
  ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(12, 0, 8.5, 5)).ok());
  EXPECT_EQ(hub_->GetTask(task_id_)->replans(), 1);
  // No state, no time: the wall-clock ticker (10 Hz) does not move this task.
  const std::size_t before = session_.messages().size();
  absl::SleepFor(absl::Milliseconds(350));
  EXPECT_EQ(session_.messages().size(), before);
}

TEST_F(SimulatedClockTest, StepDoneFollowsEveryCommandTheStepCaused) {
  const api::RobotCommand navigate = session_.Last();
  ASSERT_TRUE(navigate.has_navigate());
  // The robot reports the goal reached: held until the state that ends the step.
  api::CommandFeedback reached;
  reached.set_command_id(navigate.command_id());
  reached.set_kind(api::FEEDBACK_KIND_GOAL_REACHED);
  const std::size_t before = session_.messages().size();
  ASSERT_TRUE(hub_->OnFeedback(&session_, reached).ok());
  EXPECT_EQ(session_.messages().size(), before);

  ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(0, 0, 4.0, 9)).ok());
  const std::vector<api::ConnectResponse> messages = session_.messages();
  ASSERT_GT(messages.size(), before + 1);
  // The backtrack subgoal ended on the feedback: the task finished, with its stop command sent
  // before StepDone{9}, which is the last message.
  EXPECT_EQ(hub_->GetTask(task_id_)->status(), api::TASK_STATUS_SUCCEEDED);
  ASSERT_TRUE(messages.back().has_step_done());
  EXPECT_EQ(messages.back().step_done().step(), 9u);
  const std::vector<std::size_t> commands = CommandIndices(messages);
  ASSERT_FALSE(commands.empty());
  EXPECT_GE(commands.back(), before);  // a command of this step, before StepDone
}

TEST_F(SimulatedClockTest, SimulatedTimeMayNotGoBack) {
  const absl::Status status = hub_->OnRobotState(&session_, StepState(12, 0, 2.5, 4));
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("state.header.stamp"), std::string::npos) << status;
}

// The next episode of the same robot id opens a new session whose clock starts at 0 again.
TEST_F(SimulatedClockTest, ANewSimulatedSessionStartsItsOwnClock) {
  hub_->CloseSession(&session_);
  RecordingSink next;
  ASSERT_TRUE(hub_->OpenSession(SimulatedHello("r1"), &next).ok());
  EXPECT_TRUE(hub_->OnRobotState(&next, StepState(0, 0, 0.0, 1)).ok());
  EXPECT_TRUE(next.messages().back().has_step_done());
  hub_->Shutdown();  // closes `next` while it exists
}

// Records the live-map age each path query accepts; plans nothing (the robot plans locally).
class AgeRecordingPlanner : public RobotLocalPlanner {
 public:
  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override {
    absl::MutexLock lock(&mu_);
    ages_ms_.push_back(query.live_map_max_age_ms);
    return std::vector<Eigen::Vector3d>{};
  }
  std::vector<int> ages_ms() {
    absl::MutexLock lock(&mu_);
    return ages_ms_;
  }

 private:
  absl::Mutex mu_;
  std::vector<int> ages_ms_;
};

// Planning may answer a wall-clock robot from a grid it fetched up to planning.live_map_max_age_ms
// ago; a simulated-clock robot always gets a grid fetched for the call, because a grid of some
// wall time is not a function of its episode.
TEST(SimulatedClockPlanningTest, OnlyWallClockSessionsAcceptAnOlderLiveMap) {
  for (const bool simulated : {true, false}) {
    GatewayConfig config;
    config.planning.live_map_max_age_ms = 400;
    AgeRecordingPlanner planner;
    GatewayHub hub(config, &ShippedLexicon(), &planner);
    hub.OnSceneGraph(SofaScene());
    RecordingSink session;
    api::SessionHello hello = SimulatedHello("r1");
    if (!simulated) hello.clear_clock();
    ASSERT_TRUE(hub.OpenSession(hello, &session).ok());
    // Past the sofa and on, 12 m: going back to it is a planned navigate.
    ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 1.0, 1)).ok());
    ASSERT_TRUE(hub.OnRobotState(&session, StepState(6, 0, 2.0, 2)).ok());
    ASSERT_TRUE(hub.OnRobotState(&session, StepState(12, 0, 3.0, 3)).ok());
    ASSERT_TRUE(hub.Submit(SubmitRequest("回到沙发那里")).ok());
    const std::vector<int> ages = planner.ages_ms();
    ASSERT_FALSE(ages.empty()) << (simulated ? "simulated" : "wall clock");
    for (int age : ages) EXPECT_EQ(age, simulated ? 0 : 400);
    hub.Shutdown();
  }
}

// Answers the slow path's match_target calls when told, reporting a latency; embeddings fail at
// once (no backend), with no latency.
class LatencyModel : public LanguageModel {
 public:
  void MatchTarget(const ModelCaller& caller, const ResolveRequest&, AnswerDone done) override {
    absl::MutexLock lock(&mu_);
    matches_.push_back({caller, std::move(done)});
  }
  void Decompose(const ModelCaller&, const DecomposeRequest&, AnswerDone done) override {
    std::thread([done = std::move(done)] {
      done(absl::UnimplementedError("no decompose"));
    }).detach();
  }
  void Ask(const ModelCaller&, const ModelQuestion&, AnswerDone done) override {
    std::thread([done = std::move(done)] { done(absl::UnimplementedError("no vision")); }).detach();
  }
  void EmbedText(const ModelCaller&, const std::string&, EmbeddingDone done) override {
    std::thread([done = std::move(done)] {
      done(absl::UnavailableError("no embedding backend"));
    }).detach();
  }
  void Stop() override {}

  std::size_t matches() {
    absl::MutexLock lock(&mu_);
    return matches_.size();
  }
  // Answers call `index` from another thread, as the proxy client does.
  std::thread AnswerLater(std::size_t index, absl::Duration wall_delay,
                          absl::Duration reported_latency, std::string answer) {
    absl::MutexLock lock(&mu_);
    Call call = matches_[index];
    return std::thread([call, wall_delay, reported_latency, answer] {
      absl::SleepFor(wall_delay);
      if (call.caller.reported_latency != nullptr) *call.caller.reported_latency = reported_latency;
      call.done(answer);
    });
  }

 private:
  struct Call {
    ModelCaller caller;
    AnswerDone done;
  };
  absl::Mutex mu_;
  std::vector<Call> matches_;
};

TEST(SimulatedClockModelTest, AnAnswerIsUsedOnlyOnceItsSimulatedLatencyHasPassed) {
  RobotLocalPlanner planner;
  LatencyModel model;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner,
                 GatewayBackends{nullptr, &model, nullptr});
  hub.OnSceneGraph(CupScene());
  RecordingSink session;
  ASSERT_TRUE(hub.OpenSession(SimulatedHello("r1"), &session).ok());
  ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 10.0, 1)).ok());
  absl::StatusOr<api::SubmitInstructionResponse> submitted =
      hub.Submit(SubmitRequest("find the red cup"));
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  const std::string task_id = submitted->task_id();
  ASSERT_EQ(model.matches(), 1u);  // asked at t = 10 s

  // The answer comes back at once in wall time, but the model took 2 s of simulated time.
  const std::string pick =
      R"({"best_id": "7", "confidence": 0.8, "ranking": [{"id": "7", "score": 0.8}]})";
  model.AnswerLater(0, absl::ZeroDuration(), absl::Seconds(2), pick).join();
  ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 11.0, 2)).ok());
  EXPECT_FALSE(hub.GetTask(task_id)->has_target());
  ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 11.5, 3)).ok());
  EXPECT_FALSE(hub.GetTask(task_id)->has_target());
  ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 12.0, 4)).ok());
  ASSERT_TRUE(hub.GetTask(task_id)->has_target());
  EXPECT_EQ(hub.GetTask(task_id)->target().path(), api::RESOLUTION_PATH_SLOW);
  // The approach it caused went out before StepDone{4}.
  const std::vector<api::ConnectResponse> messages = session.messages();
  ASSERT_TRUE(messages.back().has_step_done());
  EXPECT_EQ(messages.back().step_done().step(), 4u);
  ASSERT_TRUE(messages[messages.size() - 2].has_command());
  EXPECT_DOUBLE_EQ(messages[messages.size() - 2].command().navigate().max_speed_mps(), 0.15);
  hub.Shutdown();
}

TEST(SimulatedClockModelTest, AStepWaitsForAnAnswerStillOnTheWaySoWallSpeedDoesNotMatter) {
  RobotLocalPlanner planner;
  LatencyModel model;
  GatewayHub hub(GatewayConfig{}, &ShippedLexicon(), &planner,
                 GatewayBackends{nullptr, &model, nullptr});
  hub.OnSceneGraph(CupScene());
  RecordingSink session;
  ASSERT_TRUE(hub.OpenSession(SimulatedHello("r1"), &session).ok());
  ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 10.0, 1)).ok());
  absl::StatusOr<api::SubmitInstructionResponse> submitted =
      hub.Submit(SubmitRequest("find the red cup"));
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  ASSERT_EQ(model.matches(), 1u);

  // A slow model in wall time (300 ms) with 0.5 s of simulated latency: the state at t = 11 s
  // waits for it and applies it, as it would have had the model answered at once.
  std::thread answer = model.AnswerLater(
      0, absl::Milliseconds(300), absl::Seconds(0.5),
      R"({"best_id": "7", "confidence": 0.8, "ranking": [{"id": "7", "score": 0.8}]})");
  const absl::Time started = absl::Now();
  ASSERT_TRUE(hub.OnRobotState(&session, StepState(0, 0, 11.0, 2)).ok());
  EXPECT_GE(absl::Now() - started, absl::Milliseconds(250));
  EXPECT_TRUE(hub.GetTask(submitted->task_id())->has_target());
  answer.join();
  hub.Shutdown();
}

}  // namespace
}  // namespace semnav::reasoning
