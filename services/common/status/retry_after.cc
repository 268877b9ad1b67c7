#include "services/common/status/retry_after.h"

#include <cmath>
#include <string>

#include "absl/strings/ascii.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_format.h"

namespace semnav {
namespace {

constexpr char kRetryAfterUrl[] = "semnav/retry-after-s";
constexpr double kMaxRetryAfterS = 86400.0;

}  // namespace

void SetRetryAfter(absl::Status& status, absl::Duration after) {
  if (status.ok() || after < absl::ZeroDuration() || after == absl::InfiniteDuration()) return;
  status.SetPayload(kRetryAfterUrl, absl::Cord(RetryAfterSecondsText(after)));
}

std::optional<absl::Duration> RetryAfter(const absl::Status& status) {
  const absl::optional<absl::Cord> payload = status.GetPayload(kRetryAfterUrl);
  if (!payload.has_value()) return std::nullopt;
  return ParseRetryAfterSeconds(std::string(*payload));
}

std::optional<absl::Duration> ParseRetryAfterSeconds(absl::string_view value) {
  double seconds = 0.0;
  if (!absl::SimpleAtod(absl::StripAsciiWhitespace(value), &seconds) || !(seconds >= 0.0) ||
      seconds > kMaxRetryAfterS) {
    return std::nullopt;
  }
  return absl::Seconds(seconds);
}

std::string RetryAfterSecondsText(absl::Duration after) {
  return absl::StrFormat("%.3f", absl::ToDoubleSeconds(after));
}

}  // namespace semnav
