#pragma once
// Extracts the JSON object a model was asked for from its answer text. Models without a native
// JSON mode often wrap it in a ```json fence; anything else that is not one object is DATA_LOSS
// (a malformed answer, which sends the call to the next backend).
#include <string>

#include "absl/status/statusor.h"
#include "nlohmann/json.hpp"

namespace semnav::modelproxy {

absl::StatusOr<nlohmann::json> ParseJsonAnswer(const std::string& text);

}  // namespace semnav::modelproxy
