#include "services/common/config/secret.h"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"

namespace semnav {

absl::StatusOr<std::string> ReadSecretFile(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    return absl::NotFoundError(absl::StrCat("secret file '", path, "' does not exist"));
  }
  if ((info.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    return absl::FailedPreconditionError(absl::StrCat(
        "secret file '", path, "' must not be readable by group or others (chmod 600)"));
  }
  std::ifstream in(path);
  if (!in)
    return absl::PermissionDeniedError(absl::StrCat("secret file '", path, "' cannot be read"));
  std::stringstream content;
  content << in.rdbuf();
  std::string secret(absl::StripAsciiWhitespace(content.str()));
  if (secret.empty())
    return absl::FailedPreconditionError(absl::StrCat("secret file '", path, "' is empty"));
  return secret;
}

absl::StatusOr<std::string> ReadSecretEnv(const std::string& variable) {
  const char* value = std::getenv(variable.c_str());
  if (value == nullptr || *value == '\0') {
    return absl::NotFoundError(absl::StrCat("environment variable ", variable, " is not set"));
  }
  return std::string(absl::StripAsciiWhitespace(value));
}

}  // namespace semnav
