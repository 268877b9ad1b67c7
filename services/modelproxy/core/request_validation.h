#pragma once
// Checks a caller's request before any backend sees it. Errors are INVALID_ARGUMENT with an
// ErrorInfo field (InvalidField) as the proto spells it (e.g.
// "messages[0].parts[1].image.data"); a bad value is never echoed beyond a short prefix.
// The limits are documented in docs/protocol.md (Model proxy).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "services/common/status/value_checks.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

inline constexpr int kMaxTokensLimit = 32768;
inline constexpr double kMaxTemperature = 2.0;
// Aliases and caller ids: the common id limit.
inline constexpr size_t kMaxAliasBytes = kMaxIdBytes;
inline constexpr size_t kMaxMessages = 256;
inline constexpr size_t kMaxPartsPerMessage = 64;
// All text parts of one request together (~64k tokens, more than any configured context).
inline constexpr size_t kMaxPromptTextBytes = 256u << 10;
inline constexpr size_t kMaxJsonSchemaBytes = 64u << 10;
inline constexpr size_t kMaxImagesPerRequest = 16;
// One image file, and all images of a request together.
inline constexpr size_t kMaxImageBytes = 20u << 20;
// Decoded size a PNG/JPEG header may declare: a small file can claim a huge raster.
inline constexpr uint32_t kMaxImageSidePixels = 8192;
inline constexpr size_t kMaxEmbeddingTexts = 256;
inline constexpr size_t kMaxEmbeddingTextBytes = 8u << 10;

absl::Status ValidateCompletionRequest(const CompletionRequest& request);
absl::Status ValidateEmbeddingRequest(const EmbeddingRequest& request);
// model_alias within kMaxAliasBytes (checked before the alias is looked up or echoed).
absl::Status ValidateAlias(absl::string_view alias);

// (width, height) from a PNG IHDR or a JPEG start-of-frame header; nullopt when `data` is not
// a well-formed file of that type.
std::optional<std::pair<uint32_t, uint32_t>> ImageDimensions(absl::string_view data,
                                                             absl::string_view mime);

}  // namespace semnav::modelproxy
