#include "services/modelproxy/core/api_key.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "services/common/config/secret.h"

namespace semnav::modelproxy {

ApiKey ApiKey::FromEnv(const std::string& env_name) {
  absl::StatusOr<std::string> value = ReadSecretEnv(env_name);
  return ApiKey(value.ok() ? *std::move(value) : "", absl::StrCat("env ", env_name));
}

absl::StatusOr<ApiKey> ApiKey::FromFile(const std::string& path) {
  absl::StatusOr<std::string> value = ReadSecretFile(path);
  if (!value.ok()) return value.status();
  return ApiKey(*std::move(value), absl::StrCat("file ", path));
}

std::string ApiKey::Redact(absl::string_view text) const {
  if (value_.empty()) return std::string(text);
  return absl::StrReplaceAll(std::string(text), {{value_, "[redacted]"}});
}

}  // namespace semnav::modelproxy
