#include "services/modelproxy/core/dashscope_wire.h"

#include <gtest/gtest.h>

#include "nlohmann/json.hpp"

namespace semnav::modelproxy {
namespace {

CompletionRequest Request(bool with_image) {
  CompletionRequest r;
  r.messages = {ChatMessage{Role::kSystem, {ContentPart{"sys", "", ""}}},
                ChatMessage{Role::kUser, {ContentPart{"find the helmet", "", ""}}}};
  if (with_image) r.messages[1].parts.push_back(ContentPart{"", "\x01", "image/png"});
  return r;
}

TEST(ModelProxyDashScopeWireTest, TextAndMultimodalUseTheirOwnEndpointsAndShapes) {
  DashScopeWire wire;
  EXPECT_EQ(wire.ChatPath(Request(false)), "/services/aigc/text-generation/generation");
  EXPECT_EQ(wire.ChatPath(Request(true)), "/services/aigc/multimodal-generation/generation");

  const nlohmann::json text =
      nlohmann::json::parse(wire.ChatBody(Request(false), "qwen-plus", 256));
  EXPECT_EQ(text["input"]["messages"][0]["content"], "sys");
  EXPECT_EQ(text["input"]["messages"][1]["content"], "find the helmet");
  EXPECT_EQ(text["parameters"]["result_format"], "message");
  EXPECT_EQ(text["parameters"]["max_tokens"], 256);

  const nlohmann::json mm =
      nlohmann::json::parse(wire.ChatBody(Request(true), "qwen3-vl-plus", 256));
  EXPECT_EQ(mm["input"]["messages"][0]["content"][0]["text"], "sys");
  EXPECT_EQ(mm["input"]["messages"][1]["content"][1]["image"], "data:image/png;base64,AQ==");
}

TEST(ModelProxyDashScopeWireTest, SchemaIsInstructedAndJsonObjectRequested) {
  CompletionRequest r = Request(false);
  r.format = ResponseFormat::kJsonSchema;
  r.json_schema = "{}";
  const nlohmann::json body = nlohmann::json::parse(DashScopeWire().ChatBody(r, "qwen-plus", 256));
  EXPECT_EQ(body["parameters"]["response_format"]["type"], "json_object");
  EXPECT_EQ(body["input"]["messages"][0]["content"],
            "sys\n\nAnswer with exactly one JSON object, nothing else, that validates against this "
            "JSON schema: {}");
}

TEST(ModelProxyDashScopeWireTest, ParsesStringAndListContent) {
  DashScopeWire wire;
  auto text = wire.ParseChat(R"({"output":{"choices":[{"message":{"content":"G5A"}}]},
                                 "usage":{"input_tokens":1083,"output_tokens":18}})");
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(text->text, "G5A");
  EXPECT_EQ(text->usage.input_tokens, 1083);
  auto mm =
      wire.ParseChat(R"({"output":{"choices":[{"message":{"content":[{"text":"Code: F6A"}]}}]}})");
  ASSERT_TRUE(mm.ok());
  EXPECT_EQ(mm->text, "Code: F6A");
  EXPECT_EQ(wire.ParseChat(R"({"output":{}})").status().code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(wire.ErrorMessage(R"({"code":"Throttling","message":"slow down"})"),
            "Throttling: slow down");
}

}  // namespace
}  // namespace semnav::modelproxy
