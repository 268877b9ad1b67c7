#pragma once
// Checks a caller's request before any backend sees it. Errors are INVALID_ARGUMENT and name
// the field as the proto spells it (e.g. "messages[0].parts[1].image.mime_type").
#include "absl/status/status.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

inline constexpr int kMaxTokensLimit = 32768;
inline constexpr size_t kMaxImageBytes = 20u << 20;
inline constexpr size_t kMaxEmbeddingTexts = 256;

absl::Status ValidateCompletionRequest(const CompletionRequest& request);
absl::Status ValidateEmbeddingRequest(const EmbeddingRequest& request);

}  // namespace semnav::modelproxy
