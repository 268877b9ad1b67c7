#include "services/reasoning/core/slow_answer.h"

#include "absl/strings/match.h"
#include "gtest/gtest.h"
#include "nlohmann/json.hpp"
#include "services/common/status/field_error.h"

namespace semnav::reasoning {
namespace {

SceneGraph CupOnTable() {
  SceneGraph graph;
  SceneObject cup;
  cup.id = 42;
  cup.label = "cup";
  cup.attributes = {"red"};
  SceneObject table;
  table.id = 7;
  table.label = "dining table";
  graph.objects = {cup, table};
  graph.relations = {{42, "on", 7, 0.3}};
  return graph;
}

TEST(GatewaySlowAnswerTest, ThresholdsDecideTheAction) {
  const SceneGraph graph = CupOnTable();
  const SlowPathConfig config;
  struct Row {
    const char* answer;
    SlowAction action;
    double confidence;
  };
  const Row rows[] = {
      {R"({"best_id": "42", "confidence": 0.6, "ranking": []})", SlowAction::kGoal, 0.6},
      {R"({"best_id": "42", "confidence": 0.55, "ranking": []})", SlowAction::kExplore, 0.55},
      {R"({"best_id": "42", "confidence": 0.49, "ranking": []})", SlowAction::kVisionVerify, 0.49},
      {R"({"best_id": "", "confidence": 0.0, "ranking": []})", SlowAction::kExplore, 0.0},
      // Offline prior answers count 0.75: 0.8 -> 0.6 (accepted), 0.7 -> 0.525 (not).
      {R"({"best_id": "42", "confidence": 0.8, "ranking": [], "offline": true})", SlowAction::kGoal,
       0.6},
      {R"({"best_id": "42", "confidence": 0.7, "ranking": [], "offline": true})",
       SlowAction::kExplore, 0.525},
  };
  for (const Row& row : rows) {
    absl::StatusOr<SlowDecision> decision = ParseResolveAnswer(row.answer, graph, config);
    ASSERT_TRUE(decision.ok()) << row.answer << decision.status();
    EXPECT_EQ(decision->action, row.action) << row.answer;
    EXPECT_NEAR(decision->confidence, row.confidence, 1e-12) << row.answer;
  }
  SlowPathConfig no_vision = config;
  no_vision.vision_enabled = false;
  EXPECT_EQ(ParseResolveAnswer(rows[2].answer, graph, no_vision)->action, SlowAction::kExplore);
  absl::StatusOr<SlowDecision> explained = ParseResolveAnswer(
      R"({"best_id": "42", "confidence": 0.9, "ranking": [{"id": "42", "score": 0.9, "reason": "red cup"}]})",
      graph, config);
  EXPECT_EQ(explained->explanation, "red cup");
  EXPECT_EQ(explained->object_id, 42);
}

TEST(GatewaySlowAnswerTest, RejectsBadAnswersNamingTheField) {
  const SceneGraph graph = CupOnTable();
  const std::pair<const char*, const char*> rows[] = {
      {"I think it is the cup", "answer"},
      {R"({"best_id": "99", "confidence": 0.9})", "best_id"},
      {R"({"best_id": 42, "confidence": 0.9})", "best_id"},
      {R"({"best_id": "cup", "confidence": 0.9})", "best_id"},
      {R"({"best_id": "42", "confidence": 1.5})", "confidence"},
      {R"({"best_id": "42"})", "confidence"},
      {R"({"best_id": "42", "confidence": 0.9, "offline": "yes"})", "offline"},
  };
  for (const auto& [answer, field] : rows) {
    absl::StatusOr<SlowDecision> decision = ParseResolveAnswer(answer, graph, SlowPathConfig{});
    ASSERT_EQ(decision.status().code(), absl::StatusCode::kInvalidArgument) << answer;
    EXPECT_EQ(ErrorField(decision.status()), field) << decision.status();
  }
}

TEST(GatewaySlowAnswerTest, RequestFollowsTheMatchTargetContract) {
  TargetSpec target;
  target.name = "cup";
  target.colours = {"red"};
  target.text = "红色杯子";
  const ResolveRequest request = BuildResolveRequest("去厨房找红色杯子", target, CupOnTable());
  EXPECT_TRUE(absl::StrContains(request.prose, "去厨房找红色杯子"));
  EXPECT_TRUE(absl::StrContains(request.prose, "\"id\":42"));
  const nlohmann::json task = nlohmann::json::parse(request.task_json);
  EXPECT_EQ(task["task"], "match_target");
  EXPECT_EQ(task["target"], "red cup");
  ASSERT_EQ(task["candidates"].size(), 2u);
  EXPECT_EQ(task["candidates"][0]["id"], "42");
  EXPECT_EQ(task["candidates"][0]["description"], "red, on dining table");
  EXPECT_TRUE(nlohmann::json::parse(MatchTargetSchema()).contains("required"));
}

}  // namespace
}  // namespace semnav::reasoning
