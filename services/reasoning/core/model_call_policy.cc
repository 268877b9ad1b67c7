#include "services/reasoning/core/model_call_policy.h"

#include <algorithm>
#include <cmath>

#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::reasoning {

absl::Status ValidateModelCallPolicy(const ModelCallPolicyConfig& c) {
  if (absl::Status s = CheckRange(c.new_view_move_m, "new_view_move_m", 0.0, 1e4); !s.ok())
    return s;
  if (absl::Status s = CheckRange(c.new_view_turn_rad, "new_view_turn_rad", 0.0, M_PI); !s.ok())
    return s;
  if (absl::Status s =
          CheckRange(c.new_view_min_new_code_share, "new_view_min_new_code_share", 0.0, 1.0);
      !s.ok())
    return s;
  if (absl::Status s = CheckRange(c.backoff_initial_s, "backoff_initial_s", 0.0, 3600.0); !s.ok())
    return s;
  if (absl::Status s = CheckRange(c.backoff_multiplier, "backoff_multiplier", 1.0, 100.0); !s.ok())
    return s;
  if (absl::Status s = CheckRange(c.backoff_max_s, "backoff_max_s", c.backoff_initial_s, 86400.0);
      !s.ok())
    return s;
  if (c.max_calls < 0) return InvalidField("max_calls", "must be >= 0");
  if (c.max_tokens < 0) return InvalidField("max_tokens", "must be >= 0");
  return absl::OkStatus();
}

const char* CallVerdictName(CallVerdict verdict) {
  switch (verdict) {
    case CallVerdict::kAsk:
      return "ask";
    case CallVerdict::kSameView:
      return "same_view";
    case CallVerdict::kBackingOff:
      return "backing_off";
    case CallVerdict::kBudgetSpent:
      return "budget_spent";
  }
  return "?";
}

CallVerdict ModelCallPolicy::MayAsk(double now_s) const {
  if (budget_spent()) return CallVerdict::kBudgetSpent;
  if (now_s < retry_at_s_) return CallVerdict::kBackingOff;
  return CallVerdict::kAsk;
}

CallVerdict ModelCallPolicy::MayAskVision(double now_s, const Eigen::Vector3d& position,
                                          const Eigen::Quaterniond& orientation) const {
  if (const CallVerdict verdict = MayAsk(now_s); verdict != CallVerdict::kAsk) return verdict;
  if (!last_position_.has_value()) return CallVerdict::kAsk;
  const bool moved = (position - *last_position_).norm() >= config_.new_view_move_m;
  const bool turned = last_orientation_.angularDistance(orientation) >= config_.new_view_turn_rad;
  return moved || turned ? CallVerdict::kAsk : CallVerdict::kSameView;
}

CallVerdict ModelCallPolicy::MayAskCodes(int new_codes, int printed_codes) const {
  if (printed_codes <= 0) return CallVerdict::kSameView;  // no code the answer could name
  return new_codes >= config_.new_view_min_new_code_share * printed_codes ? CallVerdict::kAsk
                                                                          : CallVerdict::kSameView;
}

void ModelCallPolicy::OnAsked() { ++calls_; }

void ModelCallPolicy::OnAskedVision(const Eigen::Vector3d& position,
                                    const Eigen::Quaterniond& orientation) {
  OnAsked();
  last_position_ = position;
  last_orientation_ = orientation.normalized();
}

void ModelCallPolicy::OnAnswer(int64_t tokens) {
  tokens_ += std::max<int64_t>(0, tokens);
  failures_ = 0;
  retry_at_s_ = -1e300;
}

void ModelCallPolicy::OnFailure(double now_s, std::optional<double> retry_after_s) {
  const double backoff =
      std::min(config_.backoff_max_s,
               config_.backoff_initial_s * std::pow(config_.backoff_multiplier, failures_));
  ++failures_;
  // The vendor's Retry-After wins when it asks for longer (capped like the back-off).
  const double wait =
      retry_after_s.has_value() && std::isfinite(*retry_after_s)
          ? std::clamp(*retry_after_s, backoff, std::max(backoff, config_.backoff_max_s))
          : backoff;
  retry_at_s_ = now_s + wait;
}

bool ModelCallPolicy::TakeBudgetSpentNotice() {
  if (!budget_spent() || budget_noticed_) return false;
  budget_noticed_ = true;
  return true;
}

std::optional<std::string> ModelCallPolicy::CachedSlowAnswer(const std::string& question) const {
  auto it = slow_answers_.find(question);
  if (it == slow_answers_.end()) return std::nullopt;
  return it->second;
}

void ModelCallPolicy::StoreSlowAnswer(const std::string& question, std::string answer) {
  slow_answers_[question] = std::move(answer);
}

int64_t EstimateTokens(const std::string& prompt, const std::string& answer, bool with_image,
                       int64_t image_tokens) {
  return static_cast<int64_t>((prompt.size() + 3) / 4 + (answer.size() + 3) / 4) +
         (with_image ? image_tokens : 0);
}

}  // namespace semnav::reasoning
