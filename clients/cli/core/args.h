// Parsing of command-line values. Errors are INVALID_ARGUMENT naming the flag.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"

namespace semnav::cli {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
};

// "X,Y" in metres, e.g. "1.5,-2".
absl::StatusOr<Point2> ParsePoint(const std::string& flag, const std::string& text);

// A finite number, at least `min`.
absl::StatusOr<double> ParseNumber(const std::string& flag, const std::string& text, double min);

// A whole number of at least `min`.
absl::StatusOr<int64_t> ParseCount(const std::string& flag, const std::string& text, int64_t min);

// Seconds as a number ("2.5") > 0.
absl::StatusOr<absl::Duration> ParseSeconds(const std::string& flag, const std::string& text);

// The index of `text` in `choices`; the error lists them.
absl::StatusOr<std::size_t> ParseChoice(const std::string& flag, const std::string& text,
                                        const std::vector<std::string>& choices);

}  // namespace semnav::cli
