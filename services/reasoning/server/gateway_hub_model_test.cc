// The hub's slow path with a scripted model: calls are made without blocking, the robot keeps
// receiving exploration commands while the answer is pending, and the answer (delivered on
// another thread, as the proxy client does) is validated and acted on.
#include <algorithm>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "gtest/gtest.h"
#include "services/common/status/field_error.h"
#include "services/reasoning/core/robot_local_planner.h"
#include "services/reasoning/server/camera_frame.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_test_support.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

// Records calls; the test answers them later from another thread.
class ScriptedModel : public LanguageModel {
 public:
  struct Match {
    ModelCaller caller;
    ResolveRequest request;
    AnswerDone done;
  };
  void MatchTarget(const ModelCaller& caller, const ResolveRequest& request,
                   AnswerDone done) override {
    matches.push_back({caller, request, std::move(done)});
  }
  void Decompose(const ModelCaller& caller, const DecomposeRequest& request,
                 AnswerDone done) override {
    if (decompose_reply.has_value()) {  // answered at once, from another thread (the client's)
      decompose_asked.push_back(request.task_json);
      repliers.emplace_back([done = std::move(done), reply = *decompose_reply] { done(reply); });
      return;
    }
    decomposes.push_back({caller, request, std::move(done)});
  }
  ~ScriptedModel() override {
    for (std::thread& replier : repliers) replier.join();
  }
  void Ask(const ModelCaller& caller, const ModelQuestion& question, AnswerDone done) override {
    asks.push_back({caller, question, std::move(done)});
  }
  void EmbedText(const ModelCaller& caller, const std::string& text, EmbeddingDone done) override {
    embed_texts.push_back(text);
    embeds.push_back(std::move(done));
    (void)caller;
  }
  void Stop() override { ++stops; }
  void Answer(std::size_t index, absl::StatusOr<std::string> answer) {
    std::thread([&] { matches[index].done(std::move(answer)); }).join();
  }

  struct Question {
    ModelCaller caller;
    ModelQuestion question;
    AnswerDone done;
  };
  void Reply(std::size_t index, absl::StatusOr<std::string> answer) {
    std::thread([&] { asks[index].done(std::move(answer)); }).join();
  }

  struct Decomposition {
    ModelCaller caller;
    DecomposeRequest request;
    AnswerDone done;
  };
  void AnswerDecompose(std::size_t index, absl::StatusOr<std::string> answer) {
    std::thread([&] { decomposes[index].done(std::move(answer)); }).join();
  }

  std::vector<Match> matches;
  std::vector<Decomposition> decomposes;
  // When set, Decompose answers with it on its own thread and records the task part here.
  std::optional<absl::StatusOr<std::string>> decompose_reply;
  std::vector<std::string> decompose_asked;
  std::vector<std::thread> repliers;
  std::vector<Question> asks;
  std::vector<std::string> embed_texts;
  std::vector<EmbeddingDone> embeds;
  int stops = 0;
};

// The DECOMPOSITION events the hub logs.
class DecompositionEvents : public StreamSink<api::StreamEventsResponse> {
 public:
  void Send(const api::StreamEventsResponse& message) override {
    absl::MutexLock lock(&mu_);
    if (message.event().kind() == api::EVENT_KIND_DECOMPOSITION)
      messages_.push_back(message.event().message());
  }
  void Close(const grpc::Status&) override {}
  std::vector<std::string> messages() {
    absl::MutexLock lock(&mu_);
    return messages_;
  }

 private:
  absl::Mutex mu_;
  std::vector<std::string> messages_;
};

void Reached(GatewayHub& hub, RecordingSink& session, const api::RobotCommand& command) {
  api::CommandFeedback feedback;
  feedback.set_command_id(command.command_id());
  feedback.set_kind(api::FEEDBACK_KIND_GOAL_REACHED);
  ASSERT_TRUE(hub.OnFeedback(&session, feedback).ok());
}

class GatewayHubModelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    hub_.OnSceneGraph(CupScene());
    api::SessionHello hello;
    hello.set_robot_id("r1");
    ASSERT_TRUE(hub_.OpenSession(hello, &session_).ok());
    EXPECT_TRUE(hub_.OnRobotState(&session_, At(0, 0)).ok());
  }
  std::string SubmitFindRedCup() { return Submit("find the red cup"); }
  std::string Submit(const std::string& instruction) {
    api::SubmitInstructionRequest request;
    request.set_request_id(instruction);
    request.set_robot_id("r1");
    request.set_instruction(instruction);
    absl::StatusOr<api::SubmitInstructionResponse> response = hub_.Submit(request);
    EXPECT_TRUE(response.ok()) << response.status();
    return response.ok() ? response->task_id() : "";
  }

  RobotLocalPlanner planner_;
  ScriptedModel model_;
  GatewayHub hub_{GatewayConfig{}, &ShippedLexicon(), &planner_,
                  GatewayBackends{nullptr, &model_, nullptr}};
  RecordingSink session_;
};

// Open vocabulary (issue 15): "找复印机" has a verb the rules know and a thing they do not, so the
// rules find no step. The model's decompose is asked before refusing; its FIND is completed with
// APPROACH and VERIFY as the rules read "find X". The old hub refused without asking.
TEST_F(GatewayHubModelTest, InstructionTheRulesCannotReadIsAskedOfTheModelBeforeRefusing) {
  DecompositionEvents events;
  hub_.WatchEvents({}, &events);
  model_.decompose_reply = std::string(R"({"subgoals": [{"type": "FIND", "target": "复印机"}]})");
  api::SubmitInstructionRequest request;
  request.set_request_id("copier");
  request.set_robot_id("r1");
  request.set_instruction("找复印机");
  absl::StatusOr<api::SubmitInstructionResponse> response = hub_.Submit(request);
  ASSERT_TRUE(response.ok()) << response.status();
  ASSERT_EQ(model_.decompose_asked.size(), 1u);
  EXPECT_EQ(model_.decompose_asked[0], BuildDecomposeRequest("找复印机").task_json);
  EXPECT_EQ(response->task().decomposition_source(), "model");
  // decompose, the text embedding, and match_target over the cup scene's classes (no label can
  // name a copier, so the model is shown one object per class).
  EXPECT_EQ(hub_.GetTask(response->task_id())->model_calls(), 3);
  ASSERT_EQ(model_.matches.size(), 1u);
  EXPECT_NE(model_.matches[0].request.task_json.find(R"("target":"复印机")"), std::string::npos)
      << model_.matches[0].request.task_json;
  EXPECT_EQ(events.messages(),
            std::vector<std::string>{
                "model subgoals used: FIND(复印机) APPROACH(复印机) VERIFY(复印机)"});
  EXPECT_TRUE(model_.decomposes.empty());  // not asked a second time as a complex instruction
}

// Refusal stays when the model cannot read the instruction either: same code, field and reason
// as without a model, and no task.
TEST_F(GatewayHubModelTest, InstructionNeitherRulesNorModelCanReadIsRefused) {
  model_.decompose_reply = absl::StatusOr<std::string>(
      absl::InvalidArgumentError("offline: no clause with a known verb"));
  for (const std::string answer_kind : {"error", "empty plan"}) {
    if (answer_kind == "empty plan") model_.decompose_reply = std::string(R"({"subgoals": []})");
    api::SubmitInstructionRequest request;
    request.set_request_id(answer_kind);
    request.set_robot_id("r1");
    request.set_instruction("blorp the zibble");
    const absl::Status refused = hub_.Submit(request).status();
    EXPECT_EQ(refused.code(), absl::StatusCode::kInvalidArgument) << answer_kind;
    EXPECT_EQ(ErrorField(refused), "instruction") << answer_kind;
    EXPECT_EQ(refused.message(), "instruction: no actionable step understood") << answer_kind;
  }
  EXPECT_EQ(model_.decompose_asked.size(), 2u);
  api::ListTasksRequest list;
  EXPECT_EQ(hub_.ListTasks(list)->tasks_size(), 0);
}

TEST_F(GatewayHubModelTest, RobotExploresWhileTheModelThinksThenGoesToTheAnsweredObject) {
  const std::string task_id = SubmitFindRedCup();
  // One match_target call for the grounded cup, one text embedding; neither answered yet.
  ASSERT_EQ(model_.matches.size(), 1u);
  EXPECT_EQ(model_.matches[0].caller.task_id, task_id);
  EXPECT_EQ(model_.matches[0].caller.robot_id, "r1");
  EXPECT_NE(model_.matches[0].request.task_json.find(R"("id":"7")"), std::string::npos);
  ASSERT_EQ(model_.embed_texts.size(), 1u);
  EXPECT_TRUE(model_.decomposes.empty());  // a simple instruction: the rules alone decompose it
  EXPECT_EQ(hub_.GetTask(task_id)->model_calls(), 2);
  EXPECT_EQ(hub_.GetTask(task_id)->model_requests(), 1);

  // Motion does not wait: exploring now, and on arrival the robot gets the next step at once.
  const api::RobotCommand explore = session_.Last();
  ASSERT_TRUE(explore.has_navigate()) << explore.ShortDebugString();
  EXPECT_EQ(hub_.GetTask(task_id)->phase(), "exploring");
  const api::RobotState there = At(explore.navigate().goal().x(), explore.navigate().goal().y());
  ASSERT_TRUE(hub_.OnRobotState(&session_, there).ok());
  Reached(hub_, session_, explore);
  EXPECT_TRUE(session_.Last().has_navigate())
      << session_.Last().ShortDebugString();  // the next exploration goal, no turn at this one

  // The embedding backend is missing (offline default): the fast path keeps its fallback.
  std::thread([&] { model_.embeds[0](absl::UnavailableError("offline: UNIMPLEMENTED")); }).join();
  EXPECT_FALSE(hub_.GetTask(task_id)->has_target());

  // The answer: cup 7 at 0.8 >= 0.6 -> goal by the slow path; the robot approaches it.
  model_.Answer(0,
                R"({"best_id": "7", "confidence": 0.8, "ranking": [{"id": "7", "score": 0.8}]})");
  const api::TaskSnapshot task = *hub_.GetTask(task_id);
  ASSERT_TRUE(task.has_target());
  EXPECT_EQ(task.target().object_id(), 7);
  EXPECT_EQ(task.target().path(), api::RESOLUTION_PATH_SLOW);
  EXPECT_DOUBLE_EQ(task.target().confidence(), 0.8);
  const api::RobotCommand approach = session_.Last();
  ASSERT_TRUE(approach.has_navigate()) << approach.ShortDebugString();
  EXPECT_DOUBLE_EQ(approach.navigate().max_speed_mps(), 0.15);
  const Eigen::Vector2d goal(approach.navigate().goal().x(), approach.navigate().goal().y());
  EXPECT_NEAR((goal - Eigen::Vector2d(4.0, 0.0)).norm(), 0.5, 1e-9);  // APPROACH stops 0.5 m away
  EXPECT_EQ(task.model_calls(), 2);  // nothing new to ask once the target is known
}

TEST_F(GatewayHubModelTest, OfflineAnswersAreWeighedLowerAndNotInGraphKeepsExploring) {
  const std::string task_id = SubmitFindRedCup();
  // Offline prior 0.7 x 0.75 = 0.525: below 0.6, not below 0.5 -> neither goal nor vision check.
  model_.Answer(
      0,
      R"({"best_id": "7", "confidence": 0.7, "ranking": [{"id": "7", "score": 0.7}], "offline": true})");
  EXPECT_FALSE(hub_.GetTask(task_id)->has_target());
  EXPECT_EQ(hub_.GetTask(task_id)->phase(), "exploring");

  // A newer scene graph with the same candidates: the answer is reused, no call.
  SceneGraph same = CupScene();
  same.revision = 4;
  hub_.OnSceneGraph(same);
  ASSERT_EQ(model_.matches.size(), 1u);
  // A newer scene graph that changes a candidate: the executor asks again; "not in the graph" ->
  // keep exploring.
  SceneGraph graph = CupScene();
  graph.revision = 5;
  graph.objects[0].attributes.push_back("ceramic");
  hub_.OnSceneGraph(graph);
  ASSERT_EQ(model_.matches.size(), 2u);
  model_.Answer(1, R"({"best_id": "", "confidence": 0.0, "ranking": []})");
  EXPECT_FALSE(hub_.GetTask(task_id)->has_target());
  EXPECT_EQ(hub_.GetTask(task_id)->reason(), "model: keep exploring ()");
  EXPECT_EQ(hub_.GetTask(task_id)->model_calls(), 3);
}

TEST_F(GatewayHubModelTest, FailedOrMalformedAnswersKeepExploringAndSayWhy) {
  const std::string task_id = SubmitFindRedCup();
  model_.Answer(0, R"({"best_id": "99", "confidence": 0.9, "ranking": []})");  // not a candidate
  EXPECT_EQ(hub_.GetTask(task_id)->reason(),
            "model: keep exploring (model answer rejected: best_id: '99' is not a candidate)");
  SceneGraph graph = CupScene();
  graph.revision = 4;
  graph.objects[0].attributes.push_back("ceramic");
  hub_.OnSceneGraph(graph);
  ASSERT_EQ(model_.matches.size(), 2u);
  model_.Answer(1, absl::DeadlineExceededError("deadline passed during the chain"));
  EXPECT_EQ(hub_.GetTask(task_id)->reason(),
            "model: keep exploring (model call failed: deadline passed during the chain)");
  EXPECT_FALSE(hub_.GetTask(task_id)->has_target());
  // Call economy: right after a failure the next revision is not asked about (back-off).
  graph.revision = 5;
  graph.objects[0].attributes.push_back("small");
  hub_.OnSceneGraph(graph);
  EXPECT_EQ(model_.matches.size(), 2u);
  EXPECT_EQ(hub_.GetTask(task_id)->reason(),
            "model: keep exploring (model call failed: not asked (backing_off))");
}

constexpr char kComplex[] = "go to the kitchen and then find the red cup";

TEST_F(GatewayHubModelTest, ComplexInstructionStartsOnRulesAndAValidModelPlanReplacesThem) {
  DecompositionEvents events;
  hub_.WatchEvents({}, &events);
  const std::string task_id = Submit(kComplex);
  // The model is asked with the decompose task; the robot is already moving on the rule plan.
  ASSERT_EQ(model_.decomposes.size(), 1u);
  EXPECT_EQ(model_.decomposes[0].caller.task_id, task_id);
  EXPECT_EQ(model_.decomposes[0].request.task_json, BuildDecomposeRequest(kComplex).task_json);
  const api::TaskSnapshot rules = *hub_.GetTask(task_id);
  EXPECT_EQ(rules.decomposition_source(), "rules");
  EXPECT_EQ(rules.subgoals(0).type(), api::SUBGOAL_TYPE_NAVIGATE);  // NAVIGATE(kitchen) first
  const std::size_t commands_before = session_.messages().size();
  ASSERT_GT(commands_before, 0u);
  const int calls_before = rules.model_calls();
  EXPECT_EQ(calls_before, static_cast<int>(model_.decomposes.size() + model_.matches.size() +
                                           model_.embeds.size()));

  model_.AnswerDecompose(0,
                         R"({"subgoals": [{"type": "FIND", "target": "cup", "colours": ["red"]},)"
                         R"( {"type": "APPROACH", "target": "cup", "distance_m": 0.5},)"
                         R"( {"type": "VERIFY", "target": "cup"}]})");
  const api::TaskSnapshot model = *hub_.GetTask(task_id);
  EXPECT_EQ(model.decomposition_source(), "model");
  ASSERT_EQ(model.subgoals_size(), 3);
  EXPECT_EQ(model.subgoals(0).type(), api::SUBGOAL_TYPE_FIND);
  EXPECT_EQ(model.current_subgoal(), 0);
  EXPECT_GT(session_.messages().size(), commands_before);  // the new plan's first command went out
  EXPECT_EQ(events.messages(), std::vector<std::string>{
                                   "model subgoals used: FIND(red cup) APPROACH(cup) VERIFY(cup)"});
  // The new plan asks for its own target's embedding (and the slow path for the red cup).
  EXPECT_GT(model.model_calls(), calls_before);
  EXPECT_EQ(model.model_calls(), static_cast<int>(model_.decomposes.size() + model_.matches.size() +
                                                  model_.embeds.size()));
}

TEST_F(GatewayHubModelTest, RejectedOrFailedModelPlansKeepTheRulesAndSayWhy) {
  struct Case {
    absl::StatusOr<std::string> answer;
    const char* event;
  };
  const Case cases[] = {
      {R"({"subgoals": [{"type": "TELEPORT", "target": "kitchen"}]})",
       "rules kept: model answer rejected: subgoals[0].type: unknown subgoal type 'TELEPORT'"},
      {R"({"subgoals": [{"type": "NAVIGATE", "target": "kitchen"}, {"type": "FIND"}]})",
       "rules kept: model answer rejected: subgoals[1].target: FIND needs a target"},
      {R"(subgoals: FIND cup)",
       "rules kept: model answer rejected: subgoals: answer is not valid JSON"},
      // What the proxy's offline backend answers: it has no decompose task.
      {absl::InvalidArgumentError(
           "model_alias 'default': offline: INVALID_ARGUMENT: target must be a non-empty string"),
       "rules kept: model call failed: model_alias 'default': offline: INVALID_ARGUMENT: target "
       "must be a "
       "non-empty string"},
  };
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    DecompositionEvents events;
    hub_.WatchEvents({}, &events);
    const std::string task_id = Submit(absl::StrCat(kComplex, " ", i));
    const api::TaskSnapshot before = *hub_.GetTask(task_id);
    ASSERT_EQ(model_.decomposes.size(), i + 1);
    model_.AnswerDecompose(i, cases[i].answer);
    const api::TaskSnapshot after = *hub_.GetTask(task_id);
    EXPECT_EQ(after.decomposition_source(), "rules") << cases[i].event;
    ASSERT_EQ(after.subgoals_size(), before.subgoals_size());
    for (int k = 0; k < after.subgoals_size(); ++k) {
      EXPECT_EQ(after.subgoals(k).SerializeAsString(), before.subgoals(k).SerializeAsString());
    }
    EXPECT_EQ(events.messages(), std::vector<std::string>{cases[i].event});
    hub_.UnwatchEvents(&events);
  }
}

TEST_F(GatewayHubModelTest, AValidModelPlanForAPausedTaskKeepsTheRules) {
  DecompositionEvents events;
  hub_.WatchEvents({}, &events);
  const std::string task_id = Submit(kComplex);
  api::PauseTaskRequest pause;
  pause.set_request_id("pause-1");
  pause.set_task_id(task_id);
  ASSERT_TRUE(hub_.Pause(pause).ok());
  ASSERT_EQ(model_.decomposes.size(), 1u);
  model_.AnswerDecompose(0, R"({"subgoals": [{"type": "FIND", "target": "cup"}]})");
  const api::TaskSnapshot task = *hub_.GetTask(task_id);
  EXPECT_EQ(task.status(), api::TASK_STATUS_PAUSED);
  EXPECT_EQ(task.decomposition_source(), "rules");
  EXPECT_EQ(task.subgoals(0).type(), api::SUBGOAL_TYPE_NAVIGATE);
  EXPECT_EQ(events.messages(),
            std::vector<std::string>{"rules kept: the model's plan came when the task was PAUSED"});
}

TEST_F(GatewayHubModelTest, ResolveTargetRunsTheSlowPathWithoutBlockingAndReportsTheGrounding) {
  api::ResolveTargetRequest request;
  request.set_robot_id("r1");
  request.set_text("the red cup");
  request.set_allow_slow_path(true);
  absl::StatusOr<api::ResolveTargetResponse> fast = hub_.ResolveTarget(request);
  ASSERT_TRUE(fast.ok()) << fast.status();
  EXPECT_FALSE(fast->has_target());
  // The cup reports no colour (label 0.5), detector 0.9; no embedding, no relation asked:
  // (0.35 * 0.5 + 0.15 * 0.9) / 0.5 = 0.62.
  EXPECT_NEAR(fast->best_candidate().score().fused(), 0.62, 1e-9);
  ASSERT_TRUE(hub_.WantsSlowPath(request, *fast));
  std::optional<absl::StatusOr<api::ResolveTargetResponse>> result;
  hub_.ResolveSlow(request, *fast,
                   [&](absl::StatusOr<api::ResolveTargetResponse> r) { result = std::move(r); });
  EXPECT_FALSE(result.has_value());  // returned before the model answered
  ASSERT_EQ(model_.matches.size(), 1u);
  model_.Answer(
      0,
      R"({"best_id": "7", "confidence": 0.9, "ranking": [{"id": "7", "score": 0.9, "reason": "a cup"}]})");
  ASSERT_TRUE(result.has_value() && result->ok());
  const api::ResolveTargetResponse& slow = **result;
  EXPECT_EQ(slow.grounded_objects(), 1);
  EXPECT_EQ(slow.explanation(), "a cup");
  EXPECT_EQ(slow.target().object_id(), 7);
  EXPECT_EQ(slow.target().path(), api::RESOLUTION_PATH_SLOW);
  EXPECT_DOUBLE_EQ(slow.target().confidence(), 0.9);
  EXPECT_NEAR(slow.best_candidate().score().fused(), 0.62, 1e-9);  // the fast-path scores stay

  request.set_allow_slow_path(false);
  EXPECT_FALSE(hub_.WantsSlowPath(request, *fast));
}

TEST_F(GatewayHubModelTest, ShutdownStopsTheModelAndLateAnswersAreIgnored) {
  const std::string task_id = SubmitFindRedCup();
  const std::size_t sent = session_.messages().size();
  hub_.Shutdown();
  EXPECT_EQ(model_.stops, 1);
  model_.Answer(0, R"({"best_id": "7", "confidence": 0.9, "ranking": []})");
  EXPECT_EQ(session_.messages().size(), sent);
  EXPECT_FALSE(hub_.GetTask(task_id)->has_target());
}

// Records the context of every exploration request; planning has no goal to offer.
class RecordingExplorer : public ExplorationService {
 public:
  absl::StatusOr<Eigen::Vector3d> SelectGoal(const ExplorationQuery&,
                                             std::optional<ExplorationStrategy> strategy,
                                             const ExplorationContext& context) override {
    strategies.push_back(strategy);
    contexts.push_back(context);
    return absl::NotFoundError("no frontier");
  }
  std::vector<std::optional<ExplorationStrategy>> strategies;
  std::vector<ExplorationContext> contexts;
};

// A robot "uav" on the session, at the origin.
void OpenUavSession(GatewayHub& hub, RecordingSink* session) {
  api::SessionHello hello;
  hello.set_robot_id("uav");
  ASSERT_TRUE(hub.OpenSession(hello, session).ok());
  EXPECT_TRUE(hub.OnRobotState(session, At(0, 0)).ok());
}

api::SubmitInstructionRequest UavSearch(const std::string& request_id,
                                        const std::string& instruction) {
  api::SubmitInstructionRequest request;
  request.set_request_id(request_id);
  request.set_robot_id("uav");
  request.set_instruction(instruction);
  return request;
}

api::CameraFrame Frame(common::v1::ImageEncoding encoding) {
  api::CameraFrame frame;
  const cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(90, 90, 90));
  frame.mutable_image()->set_encoding(encoding);
  frame.mutable_image()->set_data(EncodePng(grey));
  frame.mutable_image()->set_width(160);
  frame.mutable_image()->set_height(120);
  frame.mutable_intrinsics()->set_width(160);
  frame.mutable_intrinsics()->set_height(120);
  frame.mutable_intrinsics()->set_fx(80);
  frame.mutable_intrinsics()->set_fy(80);
  frame.mutable_intrinsics()->set_cx(80);
  frame.mutable_intrinsics()->set_cy(60);
  frame.mutable_camera_pose()->mutable_position()->set_x(-4.0);
  frame.mutable_camera_pose()->mutable_position()->set_y(3.0);
  frame.mutable_camera_pose()->mutable_orientation()->set_w(1.0);
  return frame;
}

// `frame` taken `dx` metres further along x (a new view for the call economy once dx >= 2 m).
api::CameraFrame Moved(api::CameraFrame frame, double dx) {
  frame.mutable_camera_pose()->mutable_position()->set_x(frame.camera_pose().position().x() + dx);
  return frame;
}

// A hub with a scripted vision model and a recording explorer, a UAV session open at (0, 0).
struct EroiHub {
  explicit EroiHub(const GatewayConfig& config)
      : hub(config, &ShippedLexicon(), &planner, GatewayBackends{&explorer, &model, nullptr}) {
    OpenUavSession(hub, &session);
  }
  // Sends `frame` from the robot and answers the vision call it made, if any, with no clue.
  void ShowAndAnswer(const api::CameraFrame& frame) {
    ASSERT_TRUE(hub.OnCameraFrame(&session, frame).ok());
    if (model.asks.back().done) {
      model.Reply(model.asks.size() - 1, "No clue or passage.");
      model.asks.back().done = nullptr;
    }
  }
  // Events the hub logged that `match` accepts; -1 (and a failure) when they cannot be listed.
  int CountEvents(const std::function<bool(const api::Event&)>& match) {
    const absl::StatusOr<api::ListEventsResponse> events = hub.ListEvents(api::ListEventsRequest());
    EXPECT_TRUE(events.ok()) << events.status();
    if (!events.ok()) return -1;
    return static_cast<int>(std::count_if(events->events().begin(), events->events().end(), match));
  }
  RobotLocalPlanner planner;
  ScriptedModel model;
  RecordingExplorer explorer;
  GatewayHub hub;
  RecordingSink session;
};

// An EROI_UTILITY search over the area from `min` to `max`.
api::SubmitInstructionRequest EroiSearchOver(const std::string& request_id,
                                             const std::string& instruction,
                                             const Eigen::Vector2d& min,
                                             const Eigen::Vector2d& max) {
  api::SubmitInstructionRequest request = UavSearch(request_id, instruction);
  request.set_exploration_strategy(api::EXPLORATION_STRATEGY_EROI_UTILITY);
  api::SearchArea* area = request.mutable_search_area();
  area->set_min_x(min.x());
  area->set_min_y(min.y());
  area->set_max_x(max.x());
  area->set_max_y(max.y());
  return request;
}

// The area ahead of Frame()'s view along x.
api::SubmitInstructionRequest EroiSearchAlongX(const std::string& request_id,
                                               const std::string& instruction) {
  return EroiSearchOver(request_id, instruction, {-10.0, -10.0}, {40.0, 10.0});
}

// 5 x 4 x 1 EROIs of 2 m from (0, 0, 0): N = 20, prior 0.05.
EroiSearchConfig SmallEroiGrid() {
  EroiSearchConfig eroi;
  eroi.grid.delta = 2.0;
  eroi.grid.nx = 4;
  eroi.grid.ny = 3;
  return eroi;
}

// Seed-000 loop through the hub: frames -> VLM with codes drawn -> semantic values -> region
// score after theta = 3 records -> EROI_UTILITY exploration requests carry the values.
TEST(GatewayHubEroiTest, CameraFramesFeedSemanticValuesThatPlanningReceives) {
  GatewayConfig config;
  config.eroi = SmallEroiGrid();
  // This test follows the values; which frames are new to the model has its own test
  // (AFrameOfCodesAlreadyAskedAboutIsNotAsked): here every moved frame that prints a code asks.
  config.model_proxy.calls.new_view_min_new_code_share = 0.0;
  EroiHub fixture(config);
  GatewayHub& hub = fixture.hub;
  ScriptedModel& model = fixture.model;
  RecordingExplorer& explorer = fixture.explorer;
  RecordingSink& session = fixture.session;
  api::SubmitInstructionRequest request = UavSearch("eroi-1", "find the red backpack");
  request.set_exploration_strategy(api::EXPLORATION_STRATEGY_EROI_UTILITY);
  request.set_exploration_strategy(static_cast<api::ExplorationStrategy>(42));
  EXPECT_EQ(hub.Submit(request).status().message(), "exploration_strategy: unknown value 42");
  request.set_exploration_strategy(api::EXPLORATION_STRATEGY_EROI_UTILITY);
  absl::StatusOr<api::SubmitInstructionResponse> submitted = hub.Submit(request);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  EXPECT_EQ(submitted->task().exploration_strategy(), "EROI_UTILITY");
  ASSERT_EQ(explorer.strategies.size(), 1u);
  EXPECT_EQ(explorer.strategies[0], ExplorationStrategy::kEroiUtility);
  ASSERT_EQ(explorer.contexts[0].eroi_values.size(), 20u);  // uniform 1/N before any evidence
  EXPECT_DOUBLE_EQ(explorer.contexts[0].eroi_values[7], 0.05);
  EXPECT_TRUE(explorer.contexts[0].eroi_window_min.isApprox(Eigen::Vector2d(-1, -1)));
  EXPECT_DOUBLE_EQ(explorer.contexts[0].eroi_edge_m, 2.0);

  // Bad frames are refused by field; good ones go to the vision model one at a time.
  EXPECT_EQ(hub.OnCameraFrame(&session, Frame(common::v1::IMAGE_ENCODING_MONO8)).message(),
            "camera.image.encoding: must be PNG, JPEG or RGB8");
  ASSERT_TRUE(hub.OnCameraFrame(&session, Frame(common::v1::IMAGE_ENCODING_PNG)).ok());
  ASSERT_TRUE(
      hub.OnCameraFrame(&session, Frame(common::v1::IMAGE_ENCODING_PNG)).ok());  // busy: dropped
  ASSERT_EQ(model.asks.size(), 1u);
  EXPECT_FALSE(model.asks[0].question.png.empty());
  EXPECT_NE(model.asks[0].question.prompt.find("[red backpack]"), std::string::npos);

  // Three answers in region unit (i 2..3, j 0..1): the third asks the region score.
  // (Each next frame from 2.5 m further on: the same view is not asked about twice.)
  model.Reply(0, "Code: C2A, Description: a bag by the bench");
  ASSERT_TRUE(hub.OnCameraFrame(&session, Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 2.5)).ok());
  model.Reply(1, "Code: C2A, Description: a strap by the bench");  // names no target: no look
  ASSERT_TRUE(hub.OnCameraFrame(&session, Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 5.0)).ok());
  model.Reply(2, "Code: D1A, Description: bench");
  ASSERT_EQ(model.asks.size(), 4u);
  EXPECT_TRUE(model.asks[3].question.png.empty());  // the language model scores the region
  model.Reply(3, "5");
  EXPECT_EQ(hub.GetTask(submitted->task_id())->model_calls(),
            5);  // 3 frames, 1 region, 1 embedding

  // The next exploration request carries the values: (2, 1) got C2A's evidence once (0.24; a
  // code counts once by default) then the region score 5 over k = 4 (eq. 22):
  // 0.24 + 0.76 * 5 / 20 = 0.43.
  const api::RobotCommand explore = session.Last();
  Reached(hub, session, explore);  // -> next exploration goal
  ASSERT_EQ(explorer.contexts.size(), 2u);
  EXPECT_NEAR(explorer.contexts[1].eroi_values[7], 0.43, 1e-12);
}

// Regression (issue 15, outdoor EROI paths): the model named the target at a code whose EROI the
// depth camera had already mapped, so no viewpoint there had information gain and the UAV flew
// elsewhere (with a start turn, a bench 8.6 m from road start 4 was named three times, and found
// after 180 m). With sighting_namings 2, two answers naming the target at one code now send the
// robot to look at it from 3 m, before the next exploration goal (1, the default, sends it at
// once).
TEST(GatewayHubEroiTest, ATargetTheModelNamedTwiceIsLookedAtBeforeTheNextExplorationGoal) {
  GatewayConfig config;
  config.eroi = SmallEroiGrid();
  config.eroi->sighting_namings = 2;
  config.model_proxy.calls.new_view_min_new_code_share = 0.0;
  EroiHub fixture(config);
  api::SubmitInstructionRequest request = UavSearch("eroi-look", "find the red backpack");
  request.set_exploration_strategy(api::EXPLORATION_STRATEGY_EROI_UTILITY);
  absl::StatusOr<api::SubmitInstructionResponse> submitted = fixture.hub.Submit(request);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  ASSERT_EQ(fixture.explorer.contexts.size(), 1u);
  ASSERT_TRUE(
      fixture.hub.OnCameraFrame(&fixture.session, Frame(common::v1::IMAGE_ENCODING_PNG)).ok());
  fixture.model.Reply(0, "Code: C2A, Description: a red backpack on the bench");
  // One naming is not enough: the next goal is planning's.
  Reached(fixture.hub, fixture.session, fixture.session.Last());
  ASSERT_EQ(fixture.explorer.contexts.size(), 2u);
  EXPECT_TRUE(fixture.explorer.contexts[1].eroi_sightings.empty());
  ASSERT_TRUE(
      fixture.hub.OnCameraFrame(&fixture.session, Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 2.5))
          .ok());
  fixture.model.Reply(1, "Code: C2A, Description: the backpack");
  // C2A's centre is (4, 2): planning is asked where to look at it from, 3 m away. This planning
  // has no answer, so the straight line from the robot at (0, 0) is left: (4, 2) - 3 (4, 2) /
  // |(4, 2)| = (1.317, 0.658).
  Reached(fixture.hub, fixture.session, fixture.session.Last());
  ASSERT_EQ(fixture.explorer.contexts.size(), 3u);
  ASSERT_TRUE(fixture.explorer.contexts[2].look_at.has_value());
  EXPECT_NEAR(fixture.explorer.contexts[2].look_at->x(), 4.0, 1e-9);
  EXPECT_NEAR(fixture.explorer.contexts[2].look_at->y(), 2.0, 1e-9);
  EXPECT_DOUBLE_EQ(fixture.explorer.contexts[2].look_distance_m, 3.0);
  const api::RobotCommand look = fixture.session.Last();
  ASSERT_TRUE(look.has_navigate()) << look.DebugString();
  EXPECT_NEAR(look.navigate().goal().x(), 4.0 - 12.0 / std::sqrt(20.0), 1e-6);
  EXPECT_NEAR(look.navigate().goal().y(), 2.0 - 6.0 / std::sqrt(20.0), 1e-6);
}

// Regression (issue 15, the 636-call storm): with the offline proxy every vision call failed
// fast and the next camera frame asked again, 636 calls an episode. Now a failure backs off
// (1 s, doubling) and only a new view asks: 300 frames over 30 m in well under a second of
// gateway time make one call.
TEST(GatewayHubEroiTest, FailingVisionCallsBackOffInsteadOfAskingOnEveryFrame) {
  EroiHub fixture(GatewayConfig{});
  const api::SubmitInstructionRequest request =
      EroiSearchAlongX("eroi-storm", "find the red backpack");
  ASSERT_TRUE(fixture.hub.Submit(request).ok());
  const absl::Time start = absl::Now();
  for (int i = 0; i < 300; ++i) {
    ASSERT_TRUE(
        fixture.hub
            .OnCameraFrame(&fixture.session, Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 0.1 * i))
            .ok());
    if (fixture.model.asks.size() > static_cast<size_t>(i) || i == 0) {
      const size_t last = fixture.model.asks.size() - 1;
      if (fixture.model.asks[last].done)
        fixture.model.Reply(last, absl::UnavailableError("no vision backend"));
      fixture.model.asks[last].done = nullptr;
    }
  }
  ASSERT_LT(absl::Now() - start, absl::Seconds(1))
      << "the machine is too slow for this test's timing";
  EXPECT_EQ(fixture.model.asks.size(), 1u);
}

// A robot holding still sends the same view: one call, however many frames.
TEST(GatewayHubEroiTest, OnlyANewViewIsAskedAbout) {
  EroiHub fixture(GatewayConfig{});
  const api::SubmitInstructionRequest request =
      EroiSearchAlongX("eroi-view", "find the red backpack");
  ASSERT_TRUE(fixture.hub.Submit(request).ok());
  for (int i = 0; i < 20; ++i) {
    fixture.ShowAndAnswer(Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 0.05 * i));
  }
  EXPECT_EQ(fixture.model.asks.size(), 1u);  // 0.95 m moved, not turned: the same view
  ASSERT_TRUE(
      fixture.hub.OnCameraFrame(&fixture.session, Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 2.0))
          .ok());
  EXPECT_EQ(fixture.model.asks.size(), 2u);  // 2 m from the asked frame: a new view
}

// `frame` from (x, y) at 1.5 m, turned to `yaw` (level camera).
api::CameraFrame Posed(api::CameraFrame frame, double x, double y, double yaw) {
  common::v1::Pose* pose = frame.mutable_camera_pose();
  pose->mutable_position()->set_x(x);
  pose->mutable_position()->set_y(y);
  pose->mutable_position()->set_z(1.5);
  pose->mutable_orientation()->set_w(std::cos(yaw / 2));
  pose->mutable_orientation()->set_z(std::sin(yaw / 2));
  return frame;
}

// Regression (issue 15, 42.9 vision calls per outdoor episode): a turn or a move made a new view
// even when the frame printed only codes the model had already been asked about (a UAV turning
// back, or flying on over ground it had asked about), so the task's budget went on repeats. Now
// at least half the printed codes must be new to the model.
TEST(GatewayHubEroiTest, AFrameOfCodesAlreadyAskedAboutIsNotAsked) {
  EroiHub fixture(GatewayConfig{});
  const api::SubmitInstructionRequest request =
      EroiSearchOver("eroi-codes", "find the red backpack", {-20.0, -20.0}, {20.0, 20.0});
  ASSERT_TRUE(fixture.hub.Submit(request).ok());
  const auto show = [&](double yaw) {
    fixture.ShowAndAnswer(Posed(Frame(common::v1::IMAGE_ENCODING_PNG), 0.0, 0.0, yaw));
  };
  show(0.0);
  EXPECT_EQ(fixture.model.asks.size(), 1u);
  show(M_PI);  // turned round: new codes
  EXPECT_EQ(fixture.model.asks.size(), 2u);
  show(0.0);  // turned back (pi rad, a new view by the turn alone): every code asked about
  EXPECT_EQ(fixture.model.asks.size(), 2u);
  show(M_PI / 2);  // north: new codes
  EXPECT_EQ(fixture.model.asks.size(), 3u);
}

// Regression (issue 15, 33.7 vision calls per outdoor episode): frames went to the vision model
// while the task drove to, and verified, an object it had located; the search prompt asks where
// to explore, so those answers were never used before the object was confirmed or set aside.
TEST(GatewayHubEroiTest, NoVisionCallWhileTheTaskGoesForALocatedObject) {
  EroiHub fixture(GatewayConfig{});
  const api::SubmitInstructionRequest request = EroiSearchAlongX("eroi-located", "find the cup");
  absl::StatusOr<api::SubmitInstructionResponse> submitted = fixture.hub.Submit(request);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  const auto show = [&](double dx) {
    fixture.ShowAndAnswer(Moved(Frame(common::v1::IMAGE_ENCODING_PNG), dx));
  };
  show(0.0);
  show(3.0);  // exploring: a new view asks
  const size_t asked_while_exploring = fixture.model.asks.size();
  ASSERT_GE(asked_while_exploring, 2u);
  fixture.hub.OnSceneGraph(CupScene());  // the cup is located: the task drives to it
  ASSERT_NE(fixture.hub.GetTask(submitted->task_id())->phase(), "exploring");
  show(6.0);
  show(9.0);
  EXPECT_EQ(fixture.model.asks.size(), asked_while_exploring);
}

// The budget: after max_calls the task goes on without the model and says so once.
TEST(GatewayHubEroiTest, SpentModelBudgetIsANamedEventAndStopsTheCalls) {
  GatewayConfig config;
  config.model_proxy.calls.max_calls = 3;
  EroiHub fixture(config);
  const api::SubmitInstructionRequest request =
      EroiSearchAlongX("eroi-budget", "find the red backpack");
  absl::StatusOr<api::SubmitInstructionResponse> submitted = fixture.hub.Submit(request);
  ASSERT_TRUE(submitted.ok());
  for (int i = 0; i < 10; ++i) {
    fixture.ShowAndAnswer(Moved(Frame(common::v1::IMAGE_ENCODING_PNG), 3.0 * i));
  }
  EXPECT_EQ(fixture.model.asks.size(), 3u);
  const auto budget_event = [](const api::Event& event) {
    return event.kind() == api::EVENT_KIND_MODEL_BUDGET;
  };
  EXPECT_EQ(fixture.CountEvents(budget_event), 1);
  EXPECT_EQ(fixture.hub.GetTask(submitted->task_id())->status(), api::TASK_STATUS_RUNNING);
}

// ApexNav's switch through the hub: the robot's states within reach of the model's clues turn the
// search geometric; a named event says so, and planning's next request has the prior everywhere.
TEST(GatewayHubEroiTest, CluesTheRobotReachedTurnTheSearchGeometricAsANamedEvent) {
  GatewayConfig config;
  config.eroi = SmallEroiGrid();
  config.eroi->failed_clues_to_geometric = 2;
  EroiHub fixture(config);
  api::SubmitInstructionRequest request = UavSearch("eroi-geometric", "find the red backpack");
  request.set_exploration_strategy(api::EXPLORATION_STRATEGY_EROI_UTILITY);
  absl::StatusOr<api::SubmitInstructionResponse> submitted = fixture.hub.Submit(request);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  ASSERT_TRUE(
      fixture.hub.OnCameraFrame(&fixture.session, Frame(common::v1::IMAGE_ENCODING_PNG)).ok());
  // Clues at A1A = (0, 0) and E4A = (8, 6); reach = r + inspect distance = 2 + 3 m.
  fixture.model.Reply(0,
                      "Code: A1A, Description: no backpack here; road leading on\n"
                      "Code: E4A, Description: no backpack here; gate");
  const auto geometric_events = [&] {
    return fixture.CountEvents([](const api::Event& event) {
      return absl::StrContains(event.message(), "search turned geometric");
    });
  };
  ASSERT_TRUE(fixture.hub.OnRobotState(&fixture.session, At(0.0, 0.0)).ok());  // A1A
  Reached(fixture.hub, fixture.session, fixture.session.Last());
  ASSERT_EQ(fixture.explorer.contexts.size(), 2u);
  // One clue failed: the values still steer. E4A (i 4, j 3) in the corner: m = 3.
  EXPECT_NEAR(fixture.explorer.contexts[1].eroi_values[3 * 5 + 4], 0.05 * 2.0 / 3.0 + 1.0 / 3.0,
              1e-12);
  EXPECT_EQ(geometric_events(), 0);
  ASSERT_TRUE(fixture.hub.OnRobotState(&fixture.session, At(5.0, 3.0)).ok());  // 4.2 m from E4A
  EXPECT_EQ(geometric_events(), 1);
  ASSERT_TRUE(fixture.hub.OnRobotState(&fixture.session, At(8.0, 6.0)).ok());
  EXPECT_EQ(geometric_events(), 1);  // said once
  Reached(fixture.hub, fixture.session, fixture.session.Last());
  ASSERT_EQ(fixture.explorer.contexts.size(), 3u);
  EXPECT_EQ(fixture.explorer.contexts[2].eroi_values, std::vector<double>(20, 0.05));
  EXPECT_EQ(fixture.hub.GetTask(submitted->task_id())->status(), api::TASK_STATUS_RUNNING);
}

// With no configured volume, an EROI_UTILITY task's search area becomes its EROI grid (2 m
// edges): a simulated episode or an operator's box is enough for the seed-000 loop to run.
TEST(GatewayHubEroiTest, SearchAreaIsTheVolumeWhenNoneIsConfigured) {
  EroiHub fixture(GatewayConfig{});  // no eroi section
  RecordingExplorer& explorer = fixture.explorer;
  const api::SubmitInstructionRequest request =
      EroiSearchOver("eroi-area", "find the red backpack", {-6.0, 0.0}, {4.0, 8.0});
  ASSERT_TRUE(fixture.hub.Submit(request).ok());
  ASSERT_EQ(explorer.contexts.size(), 1u);
  ASSERT_EQ(explorer.contexts[0].eroi_values.size(), 20u);  // 5 x 4 centres cover 10 x 8 m
  EXPECT_TRUE(explorer.contexts[0].eroi_window_min.isApprox(Eigen::Vector2d(-6, 0)));
  EXPECT_DOUBLE_EQ(explorer.contexts[0].eroi_edge_m, 2.0);
  ASSERT_TRUE(
      fixture.hub.OnCameraFrame(&fixture.session, Frame(common::v1::IMAGE_ENCODING_PNG)).ok());
  EXPECT_EQ(fixture.model.asks.size(), 1u);  // the frame went to the vision model
}

// The operator's search area is checked by field, echoed in the snapshot and sent with every
// exploration request.
TEST(GatewayHubSearchAreaTest, SearchAreaReachesPlanning) {
  GatewayConfig config;
  RobotLocalPlanner planner;
  RecordingExplorer explorer;
  GatewayHub hub(config, &ShippedLexicon(), &planner, GatewayBackends{&explorer, nullptr, nullptr});
  RecordingSink session;
  OpenUavSession(hub, &session);
  api::SubmitInstructionRequest request = UavSearch("area-1", "find the boat");
  api::SearchArea* area = request.mutable_search_area();
  area->set_min_x(-2.0);
  area->set_min_y(-3.0);
  area->set_max_x(-2.0);  // empty
  area->set_max_y(40.0);
  EXPECT_EQ(hub.Submit(request).status().message(),
            "search_area: min_x must be < max_x and min_y < max_y");
  area->set_max_x(std::nan(""));
  EXPECT_EQ(hub.Submit(request).status().message(), "search_area.max_x: must be a finite number");
  area->set_max_x(1e6);  // beyond kMaxCoordinateM
  EXPECT_EQ(ErrorField(hub.Submit(request).status()), "search_area.max_x");
  EXPECT_TRUE(explorer.contexts.empty());  // refused tasks never explore
  area->set_max_x(45.0);
  absl::StatusOr<api::SubmitInstructionResponse> submitted = hub.Submit(request);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  EXPECT_EQ(submitted->task().search_area().max_x(), 45.0);
  EXPECT_EQ(submitted->task().search_area().min_y(), -3.0);
  ASSERT_EQ(explorer.contexts.size(), 1u);
  ASSERT_TRUE(explorer.contexts[0].search_area.has_value());
  EXPECT_TRUE(explorer.contexts[0].search_area->min.isApprox(Eigen::Vector2d(-2.0, -3.0)));
  EXPECT_TRUE(explorer.contexts[0].search_area->max.isApprox(Eigen::Vector2d(45.0, 40.0)));
}

}  // namespace
}  // namespace semnav::reasoning
