#pragma once
// Cache key of a completion request: SHA-256 of its normalized form, so requests that differ
// only in whitespace or JSON-schema key order share a key and image bytes are hashed, not kept.
#include <string>

#include "absl/strings/string_view.h"
#include "services/common/crypto/sha256.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

// Normalized request: alias, roles, texts trimmed with whitespace runs collapsed to one space,
// images as mime + SHA-256, format, schema re-serialized with sorted keys, max tokens,
// temperature rounded to 1e-3. Returned as compact JSON (readable in tests and debugging).
std::string NormalizedRequest(const CompletionRequest& request);

// Sha256Hex(NormalizedRequest(request)).
std::string RequestKey(const CompletionRequest& request);

}  // namespace semnav::modelproxy
