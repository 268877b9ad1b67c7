#include "services/reasoning/core/task_decomposer.h"

#include "gtest/gtest.h"
#include "services/reasoning/core/subgoal_json.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

TaskDecomposer MakeDecomposer() {
  absl::StatusOr<TextSegmenter> segmenter = TextSegmenter::Create();
  EXPECT_TRUE(segmenter.ok());
  return TaskDecomposer(InstructionParser(&ShippedLexicon(), *std::move(segmenter)),
                        DecomposerConfig{});
}

struct Row {
  const char* instruction;
  const char* subgoals;
  bool complex;
};

TEST(GatewayDecomposerTest, RuleTableEnglishAndChinese) {
  const Row rows[] = {
      {"去厨房找红色杯子",
       "NAVIGATE(kitchen) FIND(red cup) LOOK_AROUND() APPROACH(red cup) VERIFY(red cup)", false},
      {"go to the kitchen and find the red cup",
       "NAVIGATE(kitchen) FIND(red cup) LOOK_AROUND() APPROACH(red cup) VERIFY(red cup)", false},
      {"去红色灭火器旁边",
       "NAVIGATE(red fire extinguisher near ) APPROACH(red fire extinguisher near ) "
       "VERIFY(red fire extinguisher near )",
       false},
      {"go to the red fire extinguisher",
       "NAVIGATE(red fire extinguisher) APPROACH(red fire extinguisher) VERIFY(red fire "
       "extinguisher)",
       false},
      {"找蓝色书包",
       "FIND(blue backpack) LOOK_AROUND() APPROACH(blue backpack) VERIFY(blue backpack)", false},
      {"go to the chair near the door",
       "NAVIGATE(chair near door) APPROACH(chair near door) VERIFY(chair near door)", false},
      {"走到沙发左边的椅子那里",
       "NAVIGATE(chair left_of couch) APPROACH(chair left_of couch) VERIFY(chair left_of couch)",
       false},
      {"去卫生间", "NAVIGATE(bathroom)", false},
      {"look around", "LOOK_AROUND()", false},
      {"回到有红色沙发的房间", "BACKTRACK(red couch)", false},
      {"explore", "EXPLORE()", false},
      {"去厨房，然后找红色杯子",
       "NAVIGATE(kitchen) FIND(red cup) LOOK_AROUND() APPROACH(red cup) VERIFY(red cup)", true},
      {"find the cup and the bottle",
       "FIND(cup) LOOK_AROUND() APPROACH(cup) VERIFY(cup) FIND(bottle) LOOK_AROUND() "
       "APPROACH(bottle) "
       "VERIFY(bottle)",
       true},
      {"inspect whether the valve downstream leaks", "", true},
  };
  TaskDecomposer decomposer = MakeDecomposer();
  for (const Row& row : rows) {
    Decomposition result = decomposer.Decompose(row.instruction);
    EXPECT_EQ(DescribeSubgoals(result.subgoals), row.subgoals) << row.instruction;
    EXPECT_EQ(result.complex, row.complex) << row.instruction;
    EXPECT_EQ(result.source, "rules");
  }
}

TEST(GatewayDecomposerTest, ApproachStopsHalfAMetreAway) {
  TaskDecomposer decomposer = MakeDecomposer();
  Decomposition result = decomposer.Decompose("找蓝色书包");
  ASSERT_EQ(result.subgoals.size(), 4u);
  EXPECT_EQ(result.subgoals[2].type, SubgoalType::kApproach);
  EXPECT_DOUBLE_EQ(result.subgoals[2].distance_m, 0.5);
  EXPECT_EQ(result.subgoals[0].target.text, "蓝色书包");
}

TEST(GatewayDecomposerTest, ValidModelAnswerReplacesRulesInvalidOneIsIgnored) {
  TaskDecomposer decomposer = MakeDecomposer();
  Decomposition rules = decomposer.Decompose("去厨房，然后找红色杯子");
  Decomposition from_model = decomposer.WithModelAnswer(
      rules,
      R"({"subgoals": [{"type": "FIND", "target": "cup"}, {"type": "VERIFY", "target": "cup"}]})");
  EXPECT_EQ(from_model.source, "model");
  EXPECT_EQ(DescribeSubgoals(from_model.subgoals), "FIND(cup) VERIFY(cup)");
  Decomposition rejected =
      decomposer.WithModelAnswer(rules, R"({"subgoals": [{"type": "TELEPORT", "target": "cup"}]})");
  EXPECT_EQ(rejected.source, "rules");
  EXPECT_EQ(rejected.subgoals, rules.subgoals);
}

// A model plan's FIND of an object gets the APPROACH and VERIFY the rules give "find X"; a FIND
// already followed by them, a room and other steps are kept as they are.
TEST(GatewayDecomposerTest, CompleteFindsAddsApproachAndVerifyOnlyWhereMissing) {
  TaskDecomposer decomposer = MakeDecomposer();
  Decomposition plan = decomposer.WithModelAnswer(
      decomposer.Decompose("x"),
      R"({"subgoals": [{"type": "NAVIGATE", "target": "office"}, {"type": "FIND", "target": "复印机"},)"
      R"( {"type": "FIND", "target": "cup"}, {"type": "VERIFY", "target": "cup"}]})");
  ASSERT_EQ(plan.source, "model");
  const std::vector<Subgoal> completed = decomposer.CompleteFinds(plan.subgoals);
  EXPECT_EQ(DescribeSubgoals(completed),
            "NAVIGATE(office) FIND(复印机) APPROACH(复印机) VERIFY(复印机) FIND(cup) VERIFY(cup)");
  EXPECT_DOUBLE_EQ(completed[2].distance_m, 0.5);
}

// Hand-written model answers for a complex instruction: only the valid one replaces the rules;
// every rejection names the field that failed.
TEST(GatewayDecomposerTest, ModelAnswersAreValidatedBeforeTheyReplaceTheRules) {
  TaskDecomposer decomposer = MakeDecomposer();
  const Decomposition rules =
      decomposer.Decompose("go to the kitchen and then find the red cup near the sink");
  ASSERT_TRUE(rules.complex);
  struct Case {
    const char* answer;
    const char* source;
    const char* rejection;
  };
  const Case cases[] = {
      {R"({"subgoals": [{"type": "NAVIGATE", "target": "kitchen"},)"
       R"( {"type": "FIND", "target": "cup", "colours": ["red"], "relation": "near", "anchor": "sink"}]})",
       "model", ""},
      {R"({"subgoals": [{"type": "NAVIGATE", "target": "kitchen"}, {"type": "FLY", "target": "cup"}]})",
       "rules", "model answer rejected: subgoals[1].type: unknown subgoal type 'FLY'"},
      {R"({"subgoals": [{"type": "APPROACH", "distance_m": 0.5}]})", "rules",
       "model answer rejected: subgoals[0].target: APPROACH needs a target"},
      {R"({"subgoals": [{"type": "FIND", "target": "cup"})", "rules",
       "model answer rejected: subgoals: answer is not valid JSON"},
  };
  for (const Case& c : cases) {
    const Decomposition result = decomposer.WithModelAnswer(rules, c.answer);
    EXPECT_EQ(result.source, c.source) << c.answer;
    EXPECT_EQ(result.rejection, c.rejection) << c.answer;
    if (result.source == "rules") {
      EXPECT_EQ(result.subgoals, rules.subgoals) << c.answer;
    }
  }
  const Decomposition valid = decomposer.WithModelAnswer(rules, cases[0].answer);
  EXPECT_EQ(DescribeSubgoals(valid.subgoals), "NAVIGATE(kitchen) FIND(red cup near sink)");
  EXPECT_EQ(valid.subgoals[1].target.colours, std::vector<std::string>{"red"});
  EXPECT_EQ(valid.subgoals[1].target.anchor, "sink");
}

TEST(GatewayDecomposerTest, DecomposeRequestCarriesTheTaskObjectAndTheContract) {
  const DecomposeRequest request = BuildDecomposeRequest("去厨房，然后找红色杯子");
  EXPECT_EQ(request.task_json, R"({"instruction":"去厨房，然后找红色杯子","task":"decompose"})");
  EXPECT_NE(request.prose.find("去厨房，然后找红色杯子"), std::string::npos);
  EXPECT_NE(request.prose.find("{\"subgoals\""), std::string::npos);
}

}  // namespace
}  // namespace semnav::reasoning
