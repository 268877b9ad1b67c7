#include "services/modelproxy/core/openai_wire.h"

#include <gtest/gtest.h>

#include "nlohmann/json.hpp"

namespace semnav::modelproxy {
namespace {

CompletionRequest VisionRequest() {
  CompletionRequest r;
  r.messages = {ChatMessage{Role::kSystem, {ContentPart{"be brief", "", ""}}},
                ChatMessage{Role::kUser,
                            {ContentPart{"what is this?", "", ""},
                             ContentPart{"", std::string("\x00\x01\x02", 3), "image/png"}}}};
  r.temperature = 0.25;
  return r;
}

TEST(ModelProxyOpenAiWireTest, BodyCarriesImagesAsDataUrlsAndDefaultsMaxTokens) {
  const nlohmann::json body =
      nlohmann::json::parse(OpenAiWire().ChatBody(VisionRequest(), "gpt-4o-mini", 512));
  EXPECT_EQ(body["model"], "gpt-4o-mini");
  EXPECT_EQ(body["max_tokens"], 512);
  EXPECT_EQ(body["temperature"], 0.25);
  EXPECT_EQ(body["messages"][0]["role"], "system");
  EXPECT_EQ(body["messages"][0]["content"], "be brief");  // single text part stays a string
  EXPECT_EQ(body["messages"][1]["content"][0]["text"], "what is this?");
  EXPECT_EQ(body["messages"][1]["content"][1]["image_url"]["url"], "data:image/png;base64,AAEC");
  EXPECT_FALSE(body.contains("response_format"));
}

TEST(ModelProxyOpenAiWireTest, JsonSchemaBecomesResponseFormat) {
  CompletionRequest r = VisionRequest();
  r.format = ResponseFormat::kJsonSchema;
  r.json_schema = R"({"type":"object"})";
  r.max_tokens = 64;
  const nlohmann::json body = nlohmann::json::parse(OpenAiWire().ChatBody(r, "m", 512));
  EXPECT_EQ(body["max_tokens"], 64);
  EXPECT_EQ(body["response_format"]["type"], "json_schema");
  EXPECT_EQ(body["response_format"]["json_schema"]["schema"]["type"], "object");
}

TEST(ModelProxyOpenAiWireTest, HeadersUseBearerOnlyWithAKey) {
  EXPECT_EQ(OpenAiWire().Headers("sk-1").back(), "Authorization: Bearer sk-1");
  EXPECT_EQ(OpenAiWire().Headers("").size(), 1u);
}

TEST(ModelProxyOpenAiWireTest, ParsesAnswerModelAndUsage) {
  const auto reply = OpenAiWire().ParseChat(
      R"({"model":"gpt-4o-mini-2024","choices":[{"message":{"content":"a chair"}}],
          "usage":{"prompt_tokens":12,"completion_tokens":3}})");
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_EQ(reply->text, "a chair");
  EXPECT_EQ(reply->model, "gpt-4o-mini-2024");
  EXPECT_EQ(reply->usage.input_tokens, 12);
  EXPECT_EQ(reply->usage.output_tokens, 3);
}

TEST(ModelProxyOpenAiWireTest, MalformedBodiesAreDataLoss) {
  OpenAiWire wire;
  EXPECT_EQ(wire.ParseChat("{\"choices\": [").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(wire.ParseChat("{\"choices\": []}").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(wire.ParseChat(R"({"choices":[{"message":{"content":null}}]})").status().code(),
            absl::StatusCode::kDataLoss);
  EXPECT_EQ(wire.ParseChat("[]").status().code(), absl::StatusCode::kDataLoss);
}

// Found by tests/fuzz (model_answer): numbers beyond the target type were converted anyway
// (undefined behaviour).
TEST(ModelProxyOpenAiWireTest, OutOfRangeNumbersAreRejectedOrIgnored) {
  EXPECT_EQ(OpenAiWire::ParseEmbeddings(R"({"data":[{"index":0,"embedding":[1e300]}]})", 1)
                .status()
                .code(),
            absl::StatusCode::kDataLoss);
  const auto reply = OpenAiWire().ParseChat(
      R"({"choices":[{"message":{"content":"hi"}}],"usage":{"prompt_tokens":1e300,"completion_tokens":7.9}})");
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_EQ(reply->usage.input_tokens, 0);
  EXPECT_EQ(reply->usage.output_tokens, 7);
}

TEST(ModelProxyOpenAiWireTest, ErrorMessageReadsTheErrorObject) {
  EXPECT_EQ(OpenAiWire().ErrorMessage(R"({"error":{"message":"rate limited"}})"), "rate limited");
  EXPECT_EQ(OpenAiWire().ErrorMessage("<html>"), "");
}

TEST(ModelProxyOpenAiWireTest, EmbeddingsAreOrderedByIndexAndChecked) {
  const auto reply = OpenAiWire::ParseEmbeddings(
      R"({"model":"clip","data":[{"index":1,"embedding":[3,4]},{"index":0,"embedding":[1,2]}],
          "usage":{"prompt_tokens":6}})",
      2);
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_EQ(reply->vectors[0], (std::vector<float>{1, 2}));
  EXPECT_EQ(reply->vectors[1], (std::vector<float>{3, 4}));
  EXPECT_EQ(reply->usage.input_tokens, 6);
  EXPECT_EQ(
      OpenAiWire::ParseEmbeddings(R"({"data":[{"index":0,"embedding":[1]}]})", 2).status().code(),
      absl::StatusCode::kDataLoss);
  EXPECT_EQ(OpenAiWire::ParseEmbeddings(
                R"({"data":[{"index":0,"embedding":[1]},{"index":1,"embedding":[1,2]}]})", 2)
                .status()
                .code(),
            absl::StatusCode::kDataLoss);
  EXPECT_EQ(
      nlohmann::json::parse(OpenAiWire::EmbeddingsBody({"a", {"x", "y"}}, "clip"))["input"][1],
      "y");
}

}  // namespace
}  // namespace semnav::modelproxy
