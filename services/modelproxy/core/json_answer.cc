#include "services/modelproxy/core/json_answer.h"

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/strip.h"

namespace semnav::modelproxy {

absl::StatusOr<nlohmann::json> ParseJsonAnswer(const std::string& text) {
  absl::string_view body = absl::StripAsciiWhitespace(text);
  if (absl::ConsumePrefix(&body, "```")) {
    absl::ConsumePrefix(&body, "json");
    if (!absl::ConsumeSuffix(&body, "```"))
      return absl::DataLossError("answer has an unclosed code fence");
    body = absl::StripAsciiWhitespace(body);
  }
  nlohmann::json parsed = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (!parsed.is_object()) return absl::DataLossError("answer is not a JSON object");
  return parsed;
}

}  // namespace semnav::modelproxy
