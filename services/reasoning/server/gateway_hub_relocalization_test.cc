// The hub runs the relocalization loop (core/relocalization_loop.h) for a simulated-clock robot:
// a LOST report pauses the task and turns the robot, the objects seen during the turn go to the
// relocalizer, its answer (held until its simulated arrival) becomes the robot's map -> odom
// correction, the robot hears of it, and the task resumes with goals in the robot's odometry frame.
#include <optional>
#include <string>
#include <vector>

#include "absl/strings/match.h"
#include "absl/synchronization/mutex.h"
#include "gtest/gtest.h"
#include "services/reasoning/core/robot_local_planner.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

// Records each call; the test answers it (from its own thread, as gRPC would).
class ScriptedRelocalizer : public Relocalizer {
 public:
  void Relocalize(const std::string& map_id, const std::vector<ObservedObject>& observed,
                  std::function<void(absl::StatusOr<RelocalizationAnswer>)> done) override {
    absl::MutexLock lock(&mu_);
    map_ids.push_back(map_id);
    calls.push_back(observed);
    pending = std::move(done);
  }
  void Answer(absl::StatusOr<RelocalizationAnswer> answer) {
    std::function<void(absl::StatusOr<RelocalizationAnswer>)> done;
    {
      absl::MutexLock lock(&mu_);
      done = std::move(pending);
      pending = nullptr;
    }
    ASSERT_TRUE(done != nullptr);
    done(std::move(answer));
  }
  absl::Mutex mu_;
  std::vector<std::string> map_ids;
  std::vector<std::vector<ObservedObject>> calls;
  std::function<void(absl::StatusOr<RelocalizationAnswer>)> pending;
};

api::RobotState StepState(double x, double y, double stamp_s, uint64_t step,
                          api::LocalizationStatus status = api::LOCALIZATION_STATUS_OK) {
  api::RobotState state = At(x, y);
  state.mutable_header()->mutable_stamp()->set_seconds(static_cast<int64_t>(stamp_s));
  state.mutable_header()->mutable_stamp()->set_nanos(
      static_cast<int32_t>((stamp_s - static_cast<int64_t>(stamp_s)) * 1e9));
  state.set_step(step);
  state.set_localization(status);
  return state;
}

SceneObject Landmark(int64_t id, const std::string& label, double x, double y) {
  SceneObject object;
  object.id = id;
  object.label = label;
  object.position = Eigen::Vector3d(x, y, 0.5);
  object.detection_count = 2;
  object.embedding = {1.0f, 0.0f, 0.0f};
  object.size = Eigen::Vector3d(0.8, 0.4, 0.5);  // scale 0.8
  return object;
}

std::vector<api::ConnectResponse> Since(RecordingSink& sink, std::size_t from) {
  std::vector<api::ConnectResponse> all = sink.messages();
  return {all.begin() + static_cast<std::ptrdiff_t>(std::min(from, all.size())), all.end()};
}

template <typename Match>
std::optional<api::ConnectResponse> Find(const std::vector<api::ConnectResponse>& messages,
                                         Match match) {
  for (const api::ConnectResponse& m : messages) {
    if (match(m)) return m;
  }
  return std::nullopt;
}

class HubRelocalizationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.relocalization.channel.address = "unused";  // the backend is the scripted one
    config_.relocalization.loop.look_around_rate_rps = 0.5;
    config_.relocalization.loop.look_around_duration_s = 12.0;
    config_.relocalization.loop.query_interval_s = 0.0;  // one query at the end of the turn
    config_.relocalization.simulated_latency_s = 0.5;
    GatewayBackends backends;
    backends.relocalizer = &relocalizer_;
    hub_ = std::make_unique<GatewayHub>(config_, &ShippedLexicon(), &planner_, backends);
    hub_->OnSceneGraph(SofaScene());
    api::SessionHello hello;
    hello.set_robot_id("r1");
    hello.set_clock(api::CLOCK_KIND_SIMULATED);
    ASSERT_TRUE(hub_->OpenSession(hello, &session_).ok());
    ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(0, 0, 1.0, 1)).ok());
    ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(6, 0, 7.0, 2)).ok());
    ASSERT_TRUE(hub_->OnRobotState(&session_, StepState(12, 0, 13.0, 3)).ok());
    // A walk at the default top speed (1 m/s): no pose jump.
    api::SubmitInstructionRequest request;
    request.set_request_id("back");
    request.set_robot_id("r1");
    request.set_instruction("回到沙发那里");
    absl::StatusOr<api::SubmitInstructionResponse> response = hub_->Submit(request);
    ASSERT_TRUE(response.ok()) << response.status();
    task_id_ = response->task_id();
    ASSERT_TRUE(session_.Last().has_navigate());
    first_goal_ = session_.Last().navigate().goal();
  }
  void TearDown() override { hub_->Shutdown(); }

  GatewayConfig config_;
  RobotLocalPlanner planner_;
  ScriptedRelocalizer relocalizer_;
  std::unique_ptr<GatewayHub> hub_;
  RecordingSink session_;
  std::string task_id_;
  common::v1::Vector3 first_goal_;
};

TEST_F(HubRelocalizationTest, LostRobotIsPausedTurnedRelocalizedCorrectedAndResumedInItsOwnFrame) {
  std::size_t mark = session_.messages().size();
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 14.0, 4, api::LOCALIZATION_STATUS_LOST)).ok());
  std::vector<api::ConnectResponse> step = Since(session_, mark);
  std::optional<api::ConnectResponse> rotate = Find(step, [](const api::ConnectResponse& m) {
    return m.has_command() && m.command().has_rotate();
  });
  ASSERT_TRUE(rotate.has_value());
  EXPECT_DOUBLE_EQ(rotate->command().rotate().angular_speed_rps(), 0.5);
  EXPECT_TRUE(absl::StartsWith(rotate->command().reason(), "relocalizing"))
      << rotate->command().reason();
  std::optional<api::ConnectResponse> update =
      Find(step, [](const api::ConnectResponse& m) { return m.has_localization(); });
  ASSERT_TRUE(update.has_value());
  EXPECT_TRUE(update->localization().relocalizing());
  EXPECT_EQ(hub_->GetTask(task_id_)->status(), api::TASK_STATUS_PAUSED);

  // During the turn mapping finds three objects; the turn ends at 14 + 12 s.
  SceneGraph seen = SofaScene();
  seen.revision = 2;
  seen.objects.push_back(Landmark(11, "chair", 13, 1));
  seen.objects.push_back(Landmark(12, "table", 14, -1));
  seen.objects.push_back(Landmark(13, "lamp", 10, 2));
  hub_->OnSceneGraph(seen);
  mark = session_.messages().size();
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 20.0, 5, api::LOCALIZATION_STATUS_LOST)).ok());
  EXPECT_TRUE(relocalizer_.calls.empty());  // still turning
  for (const api::ConnectResponse& m : Since(session_, mark))
    EXPECT_FALSE(m.command().has_navigate());
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 26.0, 6, api::LOCALIZATION_STATUS_LOST)).ok());
  ASSERT_EQ(relocalizer_.calls.size(), 1u);
  EXPECT_EQ(relocalizer_.map_ids[0], "r1");  // the robot's own map by default
  ASSERT_EQ(relocalizer_.calls[0].size(), 3u);
  EXPECT_EQ(relocalizer_.calls[0][0].object_id, 11);  // nearest first: (13, 1) is 1.41 m away
  EXPECT_DOUBLE_EQ(relocalizer_.calls[0][0].scale_m, 0.8);

  // The odometry frame sits 2 m behind in the map: map = odom - (2, 0).
  RelocalizationAnswer answer;
  answer.map_from_odom = PlanarTransform{Eigen::Vector3d(-2.0, 0.0, 0.0), 0.0};
  answer.reliable = true;
  answer.inliers = 3;
  relocalizer_.Answer(answer);
  // Held until its simulated arrival (26 + 0.5 s).
  mark = session_.messages().size();
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 26.2, 7, api::LOCALIZATION_STATUS_LOST)).ok());
  EXPECT_FALSE(Find(Since(session_, mark),
                    [](const api::ConnectResponse& m) { return m.has_localization(); }));
  mark = session_.messages().size();
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 26.5, 8, api::LOCALIZATION_STATUS_LOST)).ok());
  step = Since(session_, mark);
  update = Find(step, [](const api::ConnectResponse& m) { return m.has_localization(); });
  ASSERT_TRUE(update.has_value());
  EXPECT_FALSE(update->localization().relocalizing());
  EXPECT_NEAR(update->localization().map_from_odom().position().x(), -2.0, 1e-12);
  EXPECT_EQ(hub_->GetTask(task_id_)->status(), api::TASK_STATUS_RUNNING);
  // The same goal in the map is 2 m further along +x in the robot's odometry frame.
  std::optional<api::ConnectResponse> navigate = Find(step, [](const api::ConnectResponse& m) {
    return m.has_command() && m.command().has_navigate();
  });
  ASSERT_TRUE(navigate.has_value());
  EXPECT_NEAR(navigate->command().navigate().goal().x(), first_goal_.x() + 2.0, 1e-9);
  EXPECT_NEAR(navigate->command().navigate().goal().y(), first_goal_.y(), 1e-9);

  api::ListEventsRequest events;
  events.set_task_id(task_id_);
  absl::StatusOr<api::ListEventsResponse> listed = hub_->ListEvents(events);
  ASSERT_TRUE(listed.ok());
  bool relocalized = false;
  for (const api::Event& event : listed->events()) {
    if (event.kind() == api::EVENT_KIND_RELOCALIZED) {
      relocalized = true;
      EXPECT_TRUE(absl::StrContains(event.message(), "moved by 2.00 m")) << event.message();
    }
  }
  EXPECT_TRUE(relocalized);
}

TEST_F(HubRelocalizationTest, AnOperatorResumeDuringTheTurnMovesNothing) {
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 14.0, 4, api::LOCALIZATION_STATUS_LOST)).ok());
  const std::size_t mark = session_.messages().size();
  api::ResumeTaskRequest resume;
  resume.set_request_id("resume");
  resume.set_task_id(task_id_);
  ASSERT_TRUE(hub_->Resume(resume).ok());
  ASSERT_TRUE(
      hub_->OnRobotState(&session_, StepState(12, 0, 15.0, 5, api::LOCALIZATION_STATUS_LOST)).ok());
  for (const api::ConnectResponse& m : Since(session_, mark)) {
    EXPECT_FALSE(m.command().has_navigate()) << m.ShortDebugString();
  }
}

}  // namespace
}  // namespace semnav::reasoning
