#include "services/reasoning/core/subgoal_json.h"

#include "absl/strings/match.h"
#include "gtest/gtest.h"

namespace semnav::reasoning {
namespace {

TEST(GatewaySubgoalJsonTest, AcceptsAWellFormedList) {
  absl::StatusOr<std::vector<Subgoal>> goals = ParseModelSubgoals(R"({"subgoals": [
      {"type": "NAVIGATE", "target": "kitchen"},
      {"type": "FIND", "target": "cup", "colours": ["red"], "relation": "on", "anchor": "dining table"},
      {"type": "APPROACH", "target": "cup", "distance_m": 0.5},
      {"type": "WAIT", "duration_s": 3}]})");
  ASSERT_TRUE(goals.ok()) << goals.status();
  ASSERT_EQ(goals->size(), 4u);
  EXPECT_EQ(DescribeSubgoals(*goals),
            "NAVIGATE(kitchen) FIND(red cup on dining table) APPROACH(cup) WAIT()");
  EXPECT_DOUBLE_EQ((*goals)[2].distance_m, 0.5);
  EXPECT_DOUBLE_EQ((*goals)[3].duration_s, 3.0);
}

TEST(GatewaySubgoalJsonTest, RejectsAndNamesTheBadField) {
  struct Case {
    const char* json;
    const char* field;
  };
  const Case cases[] = {
      {R"({"subgoals": [{"type": "NAVIGATE", "target": "a"}, {"type": "FLY"}]})",
       "subgoals[1].type"},
      {R"({"subgoals": [{"type": "FIND"}]})", "subgoals[0].target"},
      {R"({"subgoals": [{"type": "VERIFY", "target": ""}]})", "subgoals[0].target"},
      {R"({"subgoals": [{"target": "cup"}]})", "subgoals[0].type"},
      {R"({"subgoals": [{"type": "APPROACH", "target": "cup", "distance_m": -1}]})",
       "subgoals[0].distance_m"},
      {R"({"subgoals": [{"type": "FIND", "target": "cup", "colours": "red"}]})",
       "subgoals[0].colours"},
      {R"({"subgoals": [{"type": "WAIT", "duration_s": 1e300}]})", "subgoals[0].duration_s"},
      {R"({"subgoals": [{"type": "APPROACH", "target": "cup", "distance_m": 1e9}]})",
       "subgoals[0].distance_m"},
      {R"({"subgoals": []})", "subgoals"},
      {R"({"steps": []})", "subgoals"},
      {R"(not json)", "subgoals"},
  };
  for (const Case& c : cases) {
    absl::StatusOr<std::vector<Subgoal>> goals = ParseModelSubgoals(c.json);
    ASSERT_EQ(goals.status().code(), absl::StatusCode::kInvalidArgument) << c.json;
    EXPECT_TRUE(absl::StartsWith(goals.status().message(), std::string(c.field) + ":"))
        << c.json << " -> " << goals.status();
  }
}

}  // namespace
}  // namespace semnav::reasoning
