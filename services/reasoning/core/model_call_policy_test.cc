#include "services/reasoning/core/model_call_policy.h"

#include <gtest/gtest.h>

#include "services/common/status/field_error.h"

namespace semnav::reasoning {
namespace {

Eigen::Quaterniond Yaw(double rad) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(rad, Eigen::Vector3d::UnitZ()));
}

TEST(ModelCallPolicyTest, VisionAsksOnlyOnANewView) {
  ModelCallPolicy policy;  // 2 m or 0.5 rad
  const Eigen::Vector3d start(0, 0, 1);
  EXPECT_EQ(policy.MayAskVision(0, start, Yaw(0)), CallVerdict::kAsk);  // the first frame
  policy.OnAskedVision(start, Yaw(0));
  EXPECT_EQ(policy.MayAskVision(1, start + Eigen::Vector3d(1.9, 0, 0), Yaw(0.4)),
            CallVerdict::kSameView);
  EXPECT_EQ(policy.MayAskVision(1, start + Eigen::Vector3d(2.0, 0, 0), Yaw(0)), CallVerdict::kAsk);
  EXPECT_EQ(policy.MayAskVision(1, start, Yaw(0.5)), CallVerdict::kAsk);
  EXPECT_EQ(policy.MayAskVision(1, start, Yaw(-0.6)), CallVerdict::kAsk);
}

TEST(ModelCallPolicyTest, VisionAsksOnlyWhenHalfThePrintedCodesAreNew) {
  ModelCallPolicy policy;                                       // share 0.5
  EXPECT_EQ(policy.MayAskCodes(0, 0), CallVerdict::kSameView);  // no code the answer could name
  EXPECT_EQ(policy.MayAskCodes(2, 4), CallVerdict::kAsk);
  EXPECT_EQ(policy.MayAskCodes(1, 3), CallVerdict::kSameView);  // 0.33 < 0.5
  EXPECT_EQ(policy.MayAskCodes(7, 7), CallVerdict::kAsk);
  ModelCallPolicyConfig any;
  any.new_view_min_new_code_share = 0.0;  // every frame that prints a code
  EXPECT_EQ(ModelCallPolicy(any).MayAskCodes(0, 5), CallVerdict::kAsk);
  EXPECT_EQ(ModelCallPolicy(any).MayAskCodes(0, 0), CallVerdict::kSameView);
}

TEST(ModelCallPolicyTest, FailuresBackOffExponentiallyAndAnAnswerResets) {
  ModelCallPolicy policy;  // 1 s, x2, cap 60 s
  policy.OnFailure(10.0);
  EXPECT_EQ(policy.MayAsk(10.9), CallVerdict::kBackingOff);
  EXPECT_EQ(policy.MayAsk(11.0), CallVerdict::kAsk);
  policy.OnFailure(11.0);  // 2 s
  EXPECT_DOUBLE_EQ(policy.retry_at_s(), 13.0);
  policy.OnFailure(13.0);  // 4 s
  EXPECT_DOUBLE_EQ(policy.retry_at_s(), 17.0);
  for (int i = 0; i < 10; ++i) policy.OnFailure(20.0);
  EXPECT_DOUBLE_EQ(policy.retry_at_s(), 80.0);  // capped at 60 s
  EXPECT_EQ(policy.MayAskVision(79, Eigen::Vector3d(50, 0, 0), Yaw(0)), CallVerdict::kBackingOff);
  policy.OnAnswer(100);
  EXPECT_EQ(policy.consecutive_failures(), 0);
  EXPECT_EQ(policy.MayAsk(20.0), CallVerdict::kAsk);
}

TEST(ModelCallPolicyTest, RetryAfterIsHonouredWhenLongerThanTheBackOff) {
  ModelCallPolicy policy;
  policy.OnFailure(0.0, 7.5);
  EXPECT_DOUBLE_EQ(policy.retry_at_s(), 7.5);
  policy.OnFailure(10.0, 0.5);  // shorter than the 2 s back-off: the back-off stands
  EXPECT_DOUBLE_EQ(policy.retry_at_s(), 12.0);
  policy.OnFailure(20.0, 1e9);  // capped
  EXPECT_DOUBLE_EQ(policy.retry_at_s(), 80.0);
}

TEST(ModelCallPolicyTest, BudgetOnCallsAndTokensIsNoticedOnce) {
  ModelCallPolicyConfig config;
  config.max_calls = 3;
  config.max_tokens = 1000;
  ModelCallPolicy calls(config);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(calls.MayAsk(i), CallVerdict::kAsk);
    calls.OnAsked();
    calls.OnAnswer(10);
  }
  EXPECT_EQ(calls.MayAsk(5), CallVerdict::kBudgetSpent);
  EXPECT_EQ(calls.MayAskVision(5, Eigen::Vector3d(9, 9, 9), Yaw(2)), CallVerdict::kBudgetSpent);
  EXPECT_TRUE(calls.TakeBudgetSpentNotice());
  EXPECT_FALSE(calls.TakeBudgetSpentNotice());

  ModelCallPolicy tokens(config);
  tokens.OnAsked();
  tokens.OnAnswer(999);
  EXPECT_EQ(tokens.MayAsk(1), CallVerdict::kAsk);
  EXPECT_FALSE(tokens.TakeBudgetSpentNotice());
  tokens.OnAsked();
  tokens.OnAnswer(1);
  EXPECT_EQ(tokens.MayAsk(1), CallVerdict::kBudgetSpent);
  EXPECT_TRUE(tokens.TakeBudgetSpentNotice());
}

TEST(ModelCallPolicyTest, SlowAnswersAreReusedForTheSameQuestion) {
  ModelCallPolicy policy;
  EXPECT_FALSE(policy.CachedSlowAnswer("q1").has_value());
  policy.StoreSlowAnswer("q1", "a1");
  EXPECT_EQ(policy.CachedSlowAnswer("q1"), "a1");
  EXPECT_FALSE(policy.CachedSlowAnswer("q2").has_value());
}

TEST(ModelCallPolicyTest, EstimatedTokens) {
  EXPECT_EQ(EstimateTokens(std::string(400, 'x'), std::string(18, 'y'), false), 105);
  EXPECT_EQ(EstimateTokens("", "", true, 765), 765);
}

TEST(ModelCallPolicyTest, ConfigIsValidated) {
  ModelCallPolicyConfig config;
  EXPECT_TRUE(ValidateModelCallPolicy(config).ok());
  config.backoff_multiplier = 0.5;
  EXPECT_EQ(ErrorField(ValidateModelCallPolicy(config)), "backoff_multiplier");
  config = ModelCallPolicyConfig();
  config.max_calls = -1;
  EXPECT_EQ(ErrorField(ValidateModelCallPolicy(config)), "max_calls");
  config = ModelCallPolicyConfig();
  config.new_view_move_m = std::nan("");
  EXPECT_EQ(ErrorField(ValidateModelCallPolicy(config)), "new_view_move_m");
  config = ModelCallPolicyConfig();
  config.new_view_min_new_code_share = 1.5;
  EXPECT_EQ(ErrorField(ValidateModelCallPolicy(config)), "new_view_min_new_code_share");
}

}  // namespace
}  // namespace semnav::reasoning
