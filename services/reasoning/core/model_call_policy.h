// When a task may call the model (issue 15, call economy). The 636-call storm: every vision call
// failed fast and the next camera frame asked again. A task's calls now go through this policy:
//   - a vision call only on a new view: the camera moved or turned enough since the last asked
//   frame;
//   - after a failure, no call until an exponential back-off (or the vendor's Retry-After) ends;
//   - a budget of calls and tokens per task; once spent the task goes on without the model (the
//     gateway logs the named event EVENT_KIND_MODEL_BUDGET once);
//   - the slow path asks once per question: an answer is reused while the grounded scene graph it
//     was asked about (target and candidates) is unchanged.
// Plain value type; times are the gateway's clock in seconds.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

#include "absl/status/status.h"

namespace semnav::reasoning {

struct ModelCallPolicyConfig {
  double new_view_move_m = 2.0;    // camera travel that makes a new view (about an EROI edge / 1.5)
  double new_view_turn_rad = 0.5;  // or a turn of this much (~29 deg, half a 60 deg field of view)
  // And at least this share of the EROI codes printed into the frame must be new to the model
  // (no earlier asked frame printed them): the answer names codes, so a frame of codes already
  // asked about adds little. 0.5 = half the view new, as a turn of half the field of view or a
  // move of half the code window's depth (3-12 m) gives; a frame with no code is never asked.
  double new_view_min_new_code_share = 0.5;
  double backoff_initial_s = 1.0;   // first wait after a failure
  double backoff_multiplier = 2.0;  // each further consecutive failure
  double backoff_max_s = 60.0;
  int max_calls = 60;           // per task (vision, region, slow path, decomposition)
  int64_t max_tokens = 120000;  // per task; ~100 vision calls of seed 000's 1083 + 18 tokens
};

// INVALID_ARGUMENT naming the field for non-finite, negative or inconsistent values.
absl::Status ValidateModelCallPolicy(const ModelCallPolicyConfig& config);

enum class CallVerdict {
  kAsk,
  kSameView,     // vision only: the camera has not moved or turned enough
  kBackingOff,   // a recent failure: wait
  kBudgetSpent,  // the task goes on without the model
};
const char* CallVerdictName(CallVerdict verdict);

class ModelCallPolicy {
 public:
  explicit ModelCallPolicy(ModelCallPolicyConfig config = {}) : config_(config) {}

  // A text call (region score, slow path, decomposition) now?
  CallVerdict MayAsk(double now_s) const;
  // A vision call for a frame taken at this camera pose (map frame)?
  CallVerdict MayAskVision(double now_s, const Eigen::Vector3d& position,
                           const Eigen::Quaterniond& orientation) const;

  // A vision frame that passed MayAskVision, judged by its printed codes: kSameView when it prints
  // none, or when fewer than new_view_min_new_code_share of them are new to the model.
  CallVerdict MayAskCodes(int new_codes, int printed_codes) const;

  // A call was made (a vision call also records its view).
  void OnAsked();
  void OnAskedVision(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation);
  // The answer came; `tokens` as reported or estimated (EstimateTokens).
  void OnAnswer(int64_t tokens);
  // The call failed at `now_s`; `retry_after_s` is the vendor's Retry-After when it sent one.
  void OnFailure(double now_s, std::optional<double> retry_after_s = std::nullopt);

  // True exactly once: the first time the budget is found spent (for the named event).
  bool TakeBudgetSpentNotice();

  std::optional<std::string> CachedSlowAnswer(const std::string& question) const;
  void StoreSlowAnswer(const std::string& question, std::string answer);

  int calls() const { return calls_; }
  int64_t tokens() const { return tokens_; }
  int consecutive_failures() const { return failures_; }
  double retry_at_s() const { return retry_at_s_; }
  bool budget_spent() const { return calls_ >= config_.max_calls || tokens_ >= config_.max_tokens; }

 private:
  ModelCallPolicyConfig config_;
  int calls_ = 0;
  int64_t tokens_ = 0;
  int failures_ = 0;
  double retry_at_s_ = -1e300;
  bool budget_noticed_ = false;
  std::optional<Eigen::Vector3d> last_position_;
  Eigen::Quaterniond last_orientation_ = Eigen::Quaterniond::Identity();
  std::map<std::string, std::string> slow_answers_;  // question text -> answer
};

// Tokens of a call when the transport reports none: ~4 characters a token (the usual rule for
// English BPE vocabularies), plus `image_tokens` for an image (seed 000: ~1083 in per VLM call).
int64_t EstimateTokens(const std::string& prompt, const std::string& answer, bool with_image,
                       int64_t image_tokens = 765);

}  // namespace semnav::reasoning
