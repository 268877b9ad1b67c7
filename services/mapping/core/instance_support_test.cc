#include "services/mapping/core/instance_support.h"

#include <gtest/gtest.h>

namespace semnav::mapping {
namespace {

SceneObject Chair() {
  SceneObject chair;
  chair.label = "chair";
  // 3.0 of votes: couch 0.3 (one confusion, 10 %), bench 0.9 (30 %).
  chair.label_scores = {{"chair", 1.8}, {"couch", 0.3}, {"bench", 0.9}};
  chair.position = {0.0, 0.0, 0.5};  // the fused box: [-0.5, 0.5] x [-0.5, 0.5] x [0, 1]
  chair.size = {1.0, 1.0, 1.0};
  return chair;
}

// Hand-checked: the chair's box [-0.5, 0.5] x [-0.5, 0.5] x [0, 1] grown by 0.25 m.
TEST(InstanceSupportTest, ABoxGrownByTheMarginHoldsItsLabelsPoints) {
  const std::vector<SceneObject> objects = {Chair()};
  const InstanceSupport support(objects, 0.25, 0.25);
  EXPECT_FALSE(support.supports_all());
  EXPECT_TRUE(support("chair", {0.7f, 0.0f, 0.5f}));
  EXPECT_FALSE(support("chair", {0.8f, 0.0f, 0.5f}));
  EXPECT_TRUE(support("chair", {0.0f, -0.74f, -0.24f}));
  EXPECT_FALSE(support("chair", {0.0f, 0.0f, 1.3f}));
  EXPECT_TRUE(support("bench", {0.0f, 0.0f, 0.5f}));   // 30 % of its votes
  EXPECT_FALSE(support("couch", {0.0f, 0.0f, 0.5f}));  // 10 %: a confusion
  EXPECT_FALSE(support("table", {0.0f, 0.0f, 0.5f}));  // no instance carries it
  EXPECT_TRUE(InstanceSupport(objects, 0.25, 0.05)("couch", {0.0f, 0.0f, 0.5f}));
}

TEST(InstanceSupportTest, ALoadedInstanceHoldsItsLabelAndANegativeMarginHoldsAll) {
  SceneObject loaded = Chair();
  loaded.label_scores.clear();  // loaded from a map file: no votes yet
  const std::vector<SceneObject> objects = {loaded};
  EXPECT_TRUE(InstanceSupport(objects, 0.0, 0.25)("chair", {0.5f, 0.5f, 1.0f}));
  EXPECT_FALSE(InstanceSupport(objects, 0.0, 0.25)("bench", {0.0f, 0.0f, 0.5f}));
  const InstanceSupport off(objects, -1.0, 0.25);
  EXPECT_TRUE(off.supports_all());
  EXPECT_TRUE(off("table", {9.0f, 9.0f, 9.0f}));
}

}  // namespace
}  // namespace semnav::mapping
