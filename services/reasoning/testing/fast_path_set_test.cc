// The fixed fast-path instruction set: every instruction is decomposed by the rules and its
// primary target resolved on the apartment scene; the fast path must pick exactly the expected
// object, or stay undecided where the expectation is "-".
#include "gtest/gtest.h"
#include "services/reasoning/core/fast_resolver.h"
#include "services/reasoning/core/task_decomposer.h"
#include "services/reasoning/testing/fixture.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

TEST(GatewayFastPathSetTest, EveryInstructionResolvesAsExpected) {
  absl::StatusOr<SceneGraph> scene = testing::LoadSceneGraph(testing::FastPathScenePath());
  ASSERT_TRUE(scene.ok()) << scene.status();
  absl::StatusOr<std::vector<testing::InstructionCase>> cases =
      testing::LoadInstructionSet(testing::FastPathInstructionsPath());
  ASSERT_TRUE(cases.ok()) << cases.status();
  ASSERT_EQ(cases->size(), 32u);
  TaskDecomposer decomposer(InstructionParser(&ShippedLexicon(), *TextSegmenter::Create()),
                            DecomposerConfig{});
  FastResolver resolver(&ShippedLexicon(), FastResolverConfig{});
  int fast = 0;
  for (const testing::InstructionCase& c : *cases) {
    const Decomposition decomposition = decomposer.Decompose(c.instruction);
    const TargetSpec* target = PrimaryTarget(decomposition.subgoals);
    ASSERT_NE(target, nullptr) << c.instruction;
    const FastResolution resolution = resolver.Resolve(*target, *scene, {}, {});
    if (c.expected_object.has_value()) {
      ASSERT_TRUE(resolution.accepted)
          << c.instruction << " best fused " << (resolution.best ? resolution.best->fused : 0.0);
      EXPECT_EQ(resolution.best->object_id, *c.expected_object) << c.instruction;
      ++fast;
    } else {
      EXPECT_FALSE(resolution.accepted)
          << c.instruction << " picked " << resolution.best->object_id;
    }
  }
  EXPECT_EQ(fast, 28);  // fast_path_ratio = 28 / 32 = 0.875 (26 before issue 15's renormalisation)
}

}  // namespace
}  // namespace semnav::reasoning
