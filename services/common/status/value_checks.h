// Checks every request door applies before a value reaches core state or a robot command:
// numbers finite and of sane magnitude, strings and lists within documented limits. Each failure
// is InvalidField(field, why) and never echoes more than a short prefix of the value.
#pragma once

#include <cstddef>
#include <string>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"

namespace semnav {

// Coordinates (metres) beyond this are no place in any world semnav maps (Earth's diameter is
// 1.3e7 m); a limit for every position a request carries, unless a service configures less.
inline constexpr double kMaxCoordinateM = 1e5;
// Ids, names and labels; instructions and free text have their own, larger limits.
inline constexpr size_t kMaxIdBytes = 256;
inline constexpr size_t kMaxTextBytes = 4096;

absl::Status CheckFinite(double value, absl::string_view field);
// Finite and |value| <= max_abs.
absl::Status CheckMagnitude(double value, absl::string_view field, double max_abs);
// Finite and within [min, max].
absl::Status CheckRange(double value, absl::string_view field, double min, double max);
// A point or vector: each axis finite and |axis| <= max_abs, named "<field>.x", ".y", ".z".
absl::Status CheckPoint(double x, double y, double z, absl::string_view field, double max_abs);
absl::Status CheckLength(absl::string_view value, absl::string_view field, size_t max_bytes);
absl::Status CheckCount(size_t count, absl::string_view field, size_t max_count);

}  // namespace semnav
