#pragma once
// How one vendor's HTTP API spells a chat completion. Implementations are pure functions of
// their inputs (unit-tested without a network); HttpBackend does the I/O.
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/modelproxy/core/request.h"

namespace semnav::modelproxy {

class WireFormat {
 public:
  virtual ~WireFormat() = default;
  // Path appended to the backend's base URL, e.g. "/chat/completions".
  virtual std::string ChatPath(const CompletionRequest& request) const = 0;
  // Headers carrying the key (empty key: no auth header) plus content type.
  virtual std::vector<std::string> Headers(const std::string& api_key) const = 0;
  virtual std::string ChatBody(const CompletionRequest& request, const std::string& model,
                               int default_max_tokens) const = 0;
  // DATA_LOSS for a body that is not the expected JSON shape or has no answer text.
  virtual absl::StatusOr<BackendReply> ParseChat(const std::string& body) const = 0;
  // Human-readable error text from a non-200 body ("" if none); callers redact and truncate.
  virtual std::string ErrorMessage(const std::string& body) const = 0;
};

// Shared helpers for the wire formats.
std::string RoleName(Role role);
// "data:<mime>;base64,<...>"
std::string DataUrl(const ContentPart& image);
// All text parts of all system messages, joined by blank lines.
std::string SystemText(const CompletionRequest& request);
// JSON content type plus "Authorization: Bearer <key>" when a key is set (OpenAI, DashScope).
std::vector<std::string> BearerJsonHeaders(const std::string& api_key);
// Instruction appended for vendors without a native JSON mode.
std::string JsonInstruction(const CompletionRequest& request);

}  // namespace semnav::modelproxy
