#pragma once
// Small checked accessors over nlohmann::json, so malformed vendor bodies become DATA_LOSS
// errors instead of exceptions.
#include <string>

#include "absl/status/statusor.h"
#include "nlohmann/json.hpp"

namespace semnav::modelproxy {

// Parses without exceptions; DATA_LOSS naming `what` if `text` is not JSON.
absl::StatusOr<nlohmann::json> ParseJson(const std::string& text, const std::string& what);
// json[key] if json is an object holding key, else a null json.
const nlohmann::json& Field(const nlohmann::json& json, const char* key);
// Integer field (a float one truncated) or 0 when absent, not a number or beyond int64.
int64_t IntField(const nlohmann::json& json, const char* key);
// String field or "" when absent/not a string.
std::string StringField(const nlohmann::json& json, const char* key);

}  // namespace semnav::modelproxy
