#pragma once
// Value types of one model call: what the caller asks and what a backend answers.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/time/time.h"

namespace semnav::modelproxy {

enum class Role { kSystem, kUser, kAssistant };

// One part of a message: text, or an encoded image (PNG/JPEG/WebP file bytes).
struct ContentPart {
  std::string text;
  std::string image_data;  // encoded file bytes; non-empty means this part is an image
  std::string image_mime;  // "image/png", "image/jpeg" or "image/webp"
  bool is_image() const { return !image_data.empty(); }
};

struct ChatMessage {
  Role role = Role::kUser;
  std::vector<ContentPart> parts;
};

enum class ResponseFormat { kText, kJsonObject, kJsonSchema };

struct CompletionRequest {
  std::string alias;  // model alias naming a fallback chain
  std::vector<ChatMessage> messages;
  ResponseFormat format = ResponseFormat::kText;
  std::string json_schema;  // JSON text; only with kJsonSchema
  int max_tokens = 0;       // 0 = backend default
  double temperature = 0.0;
  bool bypass_cache = false;
};

struct Usage {
  int64_t input_tokens = 0;
  int64_t output_tokens = 0;
};

// What one backend returned for one attempt.
struct BackendReply {
  std::string text;
  std::string model;  // model name the backend reported
  Usage usage;
  bool offline = false;    // answered by the embedded offline prior
  std::string provenance;  // data source / licence note, empty for remote models
  // The time the backend says the answer took, when it says so (a simulated model, whose time is
  // simulated); the proxy then reports it instead of the wall time it measured.
  std::optional<absl::Duration> stated_latency;
};

struct EmbeddingRequest {
  std::string alias;
  std::vector<std::string> texts;
};

struct EmbeddingReply {
  std::vector<std::vector<float>> vectors;  // one per input text, same order
  std::string model;
  Usage usage;
  // As BackendReply's: a simulated encoder states its (simulated) time.
  std::optional<absl::Duration> stated_latency;
};

// Who is calling, from gRPC metadata; empty ids are accounted as "".
struct CallerId {
  std::string robot_id;
  std::string task_id;
};

}  // namespace semnav::modelproxy
