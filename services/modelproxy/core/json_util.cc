#include "services/modelproxy/core/json_util.h"

#include <cmath>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"

namespace semnav::modelproxy {

absl::StatusOr<nlohmann::json> ParseJson(const std::string& text, const std::string& what) {
  nlohmann::json parsed = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (parsed.is_discarded()) return absl::DataLossError(absl::StrCat(what, " is not valid JSON"));
  return parsed;
}

const nlohmann::json& Field(const nlohmann::json& json, const char* key) {
  static const nlohmann::json kNull;
  if (!json.is_object()) return kNull;
  auto it = json.find(key);
  return it == json.end() ? kNull : *it;
}

int64_t IntField(const nlohmann::json& json, const char* key) {
  const nlohmann::json& value = Field(json, key);
  if (value.is_number_integer()) return value.get<int64_t>();
  // A float outside int64's range (a vendor's 1e300 token count) must not reach the conversion.
  if (value.is_number_float()) {
    const double number = value.get<double>();
    if (std::isfinite(number) && std::abs(number) < 9.2e18) return static_cast<int64_t>(number);
  }
  return 0;
}

std::string StringField(const nlohmann::json& json, const char* key) {
  const nlohmann::json& value = Field(json, key);
  return value.is_string() ? value.get<std::string>() : std::string();
}

}  // namespace semnav::modelproxy
