#include "services/modelproxy/core/json_answer.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

TEST(ModelProxyJsonAnswerTest, AcceptsPlainAndFencedObjects) {
  EXPECT_EQ(ParseJsonAnswer(" {\"a\": 1} ")->at("a"), 1);
  EXPECT_EQ(ParseJsonAnswer("```json\n{\"b\": \"x\"}\n```")->at("b"), "x");
  EXPECT_EQ(ParseJsonAnswer("```\n{\"c\": true}```")->at("c"), true);
}

TEST(ModelProxyJsonAnswerTest, RejectsNonObjectsAndTruncatedJsonAsDataLoss) {
  EXPECT_EQ(ParseJsonAnswer("[1, 2]").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(ParseJsonAnswer("{\"a\": ").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(ParseJsonAnswer("Sure! {\"a\": 1}").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(ParseJsonAnswer("```json\n{\"a\": 1}").status().code(), absl::StatusCode::kDataLoss);
}

}  // namespace
}  // namespace semnav::modelproxy
