#include "services/modelproxy/core/anthropic_wire.h"

#include <gtest/gtest.h>

#include "nlohmann/json.hpp"

namespace semnav::modelproxy {
namespace {

TEST(ModelProxyAnthropicWireTest, SystemIsTopLevelImagesAreBase64SourcesAndJsonIsInstructed) {
  CompletionRequest r;
  r.messages = {ChatMessage{Role::kSystem, {ContentPart{"you guide a robot", "", ""}}},
                ChatMessage{Role::kUser,
                            {ContentPart{"", std::string("\x00\x01\x02", 3), "image/jpeg"},
                             ContentPart{"where?", "", ""}}}};
  r.format = ResponseFormat::kJsonObject;
  const nlohmann::json body = nlohmann::json::parse(AnthropicWire().ChatBody(r, "claude-x", 1024));
  EXPECT_EQ(body["max_tokens"], 1024);
  ASSERT_EQ(body["messages"].size(), 1u);  // the system message is not a chat turn
  EXPECT_EQ(body["messages"][0]["content"][0]["source"]["media_type"], "image/jpeg");
  EXPECT_EQ(body["messages"][0]["content"][0]["source"]["data"], "AAEC");
  EXPECT_EQ(body["messages"][0]["content"][1]["text"], "where?");
  EXPECT_EQ(body["system"],
            "you guide a robot\n\nAnswer with exactly one JSON object and nothing else.");
}

TEST(ModelProxyAnthropicWireTest, HeadersCarryVersionAndKey) {
  const std::vector<std::string> h = AnthropicWire().Headers("k-1");
  EXPECT_EQ(h[1], "anthropic-version: 2023-06-01");
  EXPECT_EQ(h[2], "x-api-key: k-1");
}

TEST(ModelProxyAnthropicWireTest, ParsesTextBlocksAndUsage) {
  const auto reply = AnthropicWire().ParseChat(
      R"({"model":"claude-x","content":[{"type":"text","text":"a "},{"type":"text","text":"sofa"}],
          "usage":{"input_tokens":9,"output_tokens":2}})");
  ASSERT_TRUE(reply.ok()) << reply.status();
  EXPECT_EQ(reply->text, "a sofa");
  EXPECT_EQ(reply->usage.input_tokens, 9);
  EXPECT_EQ(reply->usage.output_tokens, 2);
  EXPECT_EQ(AnthropicWire().ParseChat(R"({"content":[]})").status().code(),
            absl::StatusCode::kDataLoss);
  EXPECT_EQ(AnthropicWire().ErrorMessage(R"({"type":"error","error":{"message":"overloaded"}})"),
            "overloaded");
}

}  // namespace
}  // namespace semnav::modelproxy
