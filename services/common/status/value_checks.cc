#include "services/common/status/value_checks.h"

#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"

namespace semnav {

absl::Status CheckFinite(double value, absl::string_view field) {
  if (!std::isfinite(value)) return InvalidField(field, "must be a finite number");
  return absl::OkStatus();
}

absl::Status CheckMagnitude(double value, absl::string_view field, double max_abs) {
  if (!std::isfinite(value)) return InvalidField(field, "must be a finite number");
  if (std::abs(value) > max_abs)
    return InvalidField(field, absl::StrCat("must be within +-", max_abs));
  return absl::OkStatus();
}

absl::Status CheckRange(double value, absl::string_view field, double min, double max) {
  if (!std::isfinite(value)) return InvalidField(field, "must be a finite number");
  if (value < min || value > max)
    return InvalidField(field, absl::StrCat("must be in [", min, ", ", max, "]"));
  return absl::OkStatus();
}

absl::Status CheckPoint(double x, double y, double z, absl::string_view field, double max_abs) {
  const std::pair<double, const char*> axes[] = {{x, ".x"}, {y, ".y"}, {z, ".z"}};
  for (const auto& [value, axis] : axes) {
    if (absl::Status s = CheckMagnitude(value, absl::StrCat(field, axis), max_abs); !s.ok())
      return s;
  }
  return absl::OkStatus();
}

absl::Status CheckLength(absl::string_view value, absl::string_view field, size_t max_bytes) {
  if (value.size() > max_bytes) {
    return InvalidField(field, absl::StrCat("is ", value.size(), " bytes, more than the limit of ",
                                            max_bytes, " (starts '", Preview(value, 16), "')"));
  }
  return absl::OkStatus();
}

absl::Status CheckCount(size_t count, absl::string_view field, size_t max_count) {
  if (count > max_count)
    return InvalidField(field, absl::StrCat("has ", count, " items, more than ", max_count));
  return absl::OkStatus();
}

}  // namespace semnav
