#pragma once
// An API key read from an environment variable or a file readable only by its owner (0600 or
// stricter). The value is never printed: errors name the source, and Redact() scrubs the value
// from any text that came back from a vendor before it reaches a log or an error message.
#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace semnav::modelproxy {

class ApiKey {
 public:
  ApiKey() = default;  // no key (local servers such as Ollama or llama.cpp)

  // Reads the variable `env_name`. An unset or empty variable gives an empty key (the backend
  // then reports FAILED_PRECONDITION per call, so a stack without keys still starts).
  static ApiKey FromEnv(const std::string& env_name);
  // Reads the file via semnav::ReadSecretFile: FAILED_PRECONDITION if group/other have any
  // permission bit or it is empty, NOT_FOUND if missing. Messages name the path only.
  static absl::StatusOr<ApiKey> FromFile(const std::string& path);

  bool empty() const { return value_.empty(); }
  const std::string& value() const { return value_; }
  // Where the key came from ("env OPENAI_API_KEY", "file /etc/semnav/key"), safe to log.
  const std::string& source() const { return source_; }
  // `text` with every occurrence of the key replaced by "[redacted]".
  std::string Redact(absl::string_view text) const;

 private:
  ApiKey(std::string value, std::string source)
      : value_(std::move(value)), source_(std::move(source)) {}
  std::string value_;
  std::string source_;
};

}  // namespace semnav::modelproxy
