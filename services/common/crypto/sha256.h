#pragma once

#include <string>

#include "absl/strings/string_view.h"

namespace semnav {

// Lower-case hex SHA-256 of `bytes` (64 characters).
std::string Sha256Hex(absl::string_view bytes);

}  // namespace semnav
