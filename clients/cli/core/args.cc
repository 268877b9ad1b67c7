#include "clients/cli/core/args.h"

#include <cmath>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"

namespace semnav::cli {
namespace {

absl::Status Bad(const std::string& flag, const std::string& text, absl::string_view expected) {
  return absl::InvalidArgumentError(absl::StrCat("--", flag, ": '", text, "' is not ", expected));
}

}  // namespace

absl::StatusOr<Point2> ParsePoint(const std::string& flag, const std::string& text) {
  std::vector<std::string> parts = absl::StrSplit(text, ',');
  Point2 point;
  if (parts.size() != 2 || !absl::SimpleAtod(parts[0], &point.x) ||
      !absl::SimpleAtod(parts[1], &point.y) || !std::isfinite(point.x) || !std::isfinite(point.y)) {
    return Bad(flag, text, "a point X,Y in metres");
  }
  return point;
}

absl::StatusOr<double> ParseNumber(const std::string& flag, const std::string& text, double min) {
  double value = 0.0;
  if (!absl::SimpleAtod(text, &value) || !std::isfinite(value) || value < min) {
    return Bad(flag, text, absl::StrCat("a number >= ", min));
  }
  return value;
}

absl::StatusOr<int64_t> ParseCount(const std::string& flag, const std::string& text, int64_t min) {
  int64_t value = 0;
  if (!absl::SimpleAtoi(text, &value) || value < min)
    return Bad(flag, text, absl::StrCat("a whole number >= ", min));
  return value;
}

absl::StatusOr<absl::Duration> ParseSeconds(const std::string& flag, const std::string& text) {
  double seconds = 0.0;
  if (!absl::SimpleAtod(text, &seconds) || !std::isfinite(seconds) || seconds <= 0.0) {
    return Bad(flag, text, "a number of seconds > 0");
  }
  return absl::Seconds(seconds);
}

absl::StatusOr<std::size_t> ParseChoice(const std::string& flag, const std::string& text,
                                        const std::vector<std::string>& choices) {
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (choices[i] == text) return i;
  }
  return Bad(flag, text, absl::StrCat("one of ", absl::StrJoin(choices, ", ")));
}

}  // namespace semnav::cli
