#include "services/modelproxy/core/offline/offline_decompose.h"

#include <gtest/gtest.h>

#include "services/modelproxy/core/offline/offline_backend.h"

namespace semnav::modelproxy::offline {
namespace {

nlohmann::json Subgoals(const std::string& instruction) {
  absl::StatusOr<nlohmann::json> answer =
      DecomposeOffline({{"task", "decompose"}, {"instruction", instruction}});
  EXPECT_TRUE(answer.ok()) << instruction << ": " << answer.status();
  if (!answer.ok()) return nlohmann::json::array();
  EXPECT_EQ((*answer)["offline"], true);
  nlohmann::json goals = (*answer)["subgoals"];
  for (nlohmann::json& goal : goals) goal.erase("reason");  // checked once below
  return goals;
}

TEST(ModelProxyOfflineDecomposeTest, SplitsTheIssuesExampleIntoNavigateThenFind) {
  EXPECT_EQ(Subgoals("go to the kitchen, then find the red cup"),
            nlohmann::json::parse(R"([{"type": "NAVIGATE", "target": "kitchen"},
                                      {"type": "FIND", "target": "cup", "colours": ["red"]}])"));
  absl::StatusOr<nlohmann::json> answer = DecomposeOffline(
      {{"task", "decompose"}, {"instruction", "Go to the kitchen and then look for a mug"}});
  ASSERT_TRUE(answer.ok());
  EXPECT_EQ((*answer)["subgoals"][0]["reason"], "offline rules: \"go to the kitchen\"");
  EXPECT_EQ((*answer)["subgoals"][1]["type"], "FIND");
  EXPECT_EQ((*answer)["subgoals"][1]["target"], "cup");  // the lexicon's name for a mug
}

TEST(ModelProxyOfflineDecomposeTest, ChineseClausesColoursAndRelations) {
  EXPECT_EQ(Subgoals("先去厨房，然后找红色的杯子"),
            nlohmann::json::parse(R"([{"type": "NAVIGATE", "target": "kitchen"},
                                      {"type": "FIND", "target": "cup", "colours": ["red"]}])"));
  EXPECT_EQ(Subgoals("去卧室再找沙发旁边的书"),
            nlohmann::json::parse(R"([{"type": "NAVIGATE", "target": "bedroom"},
                                      {"type": "FIND", "target": "book", "relation": "near", "anchor": "couch"}])"));
}

TEST(ModelProxyOfflineDecomposeTest, RelationsWaitsAndAndBetweenVerbs) {
  EXPECT_EQ(
      Subgoals(
          "find the blue chair next to the table and wait 5 seconds, then go back to the door"),
      nlohmann::json::parse(R"([{"type": "FIND", "target": "chair", "colours": ["blue"],
                                       "relation": "near", "anchor": "dining table"},
                                      {"type": "WAIT", "duration_s": 5.0},
                                      {"type": "BACKTRACK", "target": "door"}])"));
  // " and " between two nouns stays inside the clause.
  EXPECT_EQ(Subgoals("look around and find the cup in the living room"),
            nlohmann::json::parse(R"([{"type": "LOOK_AROUND"},
                                      {"type": "FIND", "target": "cup", "relation": "in", "anchor": "living room"}])"));
  EXPECT_EQ(Subgoals("等2分钟")[0],
            nlohmann::json::parse(R"({"type": "WAIT", "duration_s": 120.0})"));
}

TEST(ModelProxyOfflineDecomposeTest, UnknownTargetsAreKeptAsSaid) {
  EXPECT_EQ(Subgoals("find the fire extinguisher cabinet"),
            nlohmann::json::parse(R"([{"type": "FIND", "target": "fire extinguisher cabinet"}])"));
}

TEST(ModelProxyOfflineDecomposeTest, RefusesWhatItCannotRead) {
  EXPECT_EQ(DecomposeOffline({{"task", "decompose"}}).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(DecomposeOffline({{"task", "decompose"}, {"instruction", ""}}).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(DecomposeOffline({{"task", "decompose"}, {"instruction", std::string(3000, 'a')}})
                .status()
                .code(),
            absl::StatusCode::kInvalidArgument);
  // No action at all: the gateway keeps its rule plan.
  EXPECT_EQ(DecomposeOffline({{"task", "decompose"}, {"instruction", "the weather is nice"}})
                .status()
                .code(),
            absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace semnav::modelproxy::offline
