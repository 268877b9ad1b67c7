// Vendors' HTTP answers (services/modelproxy/core): chat answers and error bodies of the OpenAI,
// Anthropic and DashScope wire formats, OpenAI embeddings, and the JSON object extracted from an
// answer's text. Every body goes through every decoder.
#include <cstdint>
#include <cstdlib>
#include <memory>

#include "services/modelproxy/core/anthropic_wire.h"
#include "services/modelproxy/core/dashscope_wire.h"
#include "services/modelproxy/core/json_answer.h"
#include "services/modelproxy/core/openai_wire.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace semnav::modelproxy;
  static const OpenAiWire openai;
  static const AnthropicWire anthropic;
  static const DashScopeWire dashscope;
  const std::string body = semnav::fuzz::AsString(data, size);
  for (const WireFormat* wire :
       {static_cast<const WireFormat*>(&openai), static_cast<const WireFormat*>(&anthropic),
        static_cast<const WireFormat*>(&dashscope)}) {
    (void)wire->ParseChat(body);
    (void)wire->ErrorMessage(body);
  }
  for (size_t expected : {size_t{1}, size_t{3}}) {
    absl::StatusOr<EmbeddingReply> reply = OpenAiWire::ParseEmbeddings(body, expected);
    if (reply.ok() && reply->vectors.size() != expected) std::abort();  // the documented promise
  }
  (void)ParseJsonAnswer(body);
  return 0;
}
