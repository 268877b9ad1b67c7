#pragma once

#include <string>

#include "absl/status/statusor.h"

namespace semnav {

// Secrets (tokens, model keys) come only from environment variables or from files that only
// their owner can read (mode 0600 or stricter). Errors name the source, never the content.
absl::StatusOr<std::string> ReadSecretFile(const std::string& path);
absl::StatusOr<std::string> ReadSecretEnv(const std::string& variable);

}  // namespace semnav
