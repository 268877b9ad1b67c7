#include "services/modelproxy/core/request_validation.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

CompletionRequest Good() {
  CompletionRequest r;
  r.messages = {ChatMessage{Role::kUser, {ContentPart{"hi", "", ""}}}};
  return r;
}

void ExpectInvalid(const CompletionRequest& r, const std::string& field) {
  const absl::Status s = ValidateCompletionRequest(r);
  EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument) << field;
  EXPECT_NE(s.message().find(field), std::string::npos) << s.message();
}

TEST(ModelProxyRequestValidationTest, AcceptsAGoodRequest) {
  EXPECT_TRUE(ValidateCompletionRequest(Good()).ok());
}

TEST(ModelProxyRequestValidationTest, NamesTheOffendingField) {
  CompletionRequest r = Good();
  r.messages.clear();
  ExpectInvalid(r, "messages");
  r = Good();
  r.messages[0].parts.push_back(ContentPart{"", "\x89PNG", "image/gif"});
  ExpectInvalid(r, "messages[0].parts[1].image.mime_type");
  r = Good();
  r.messages[0].parts[0].text = "";
  ExpectInvalid(r, "messages[0].parts[0].text");
  r = Good();
  r.messages[0].role = Role::kSystem;
  ExpectInvalid(r, "user message");
  r = Good();
  r.max_tokens = -1;
  ExpectInvalid(r, "max_tokens");
  r = Good();
  r.temperature = 2.5;
  ExpectInvalid(r, "temperature");
  r = Good();
  r.format = ResponseFormat::kJsonSchema;
  r.json_schema = "{not json";
  ExpectInvalid(r, "json_schema");
  r = Good();
  r.json_schema = "{}";
  ExpectInvalid(r, "json_schema");
}

TEST(ModelProxyRequestValidationTest, EmbeddingTextsMustBeNonEmpty) {
  EXPECT_TRUE(ValidateEmbeddingRequest({"clip", {"a chair"}}).ok());
  EXPECT_EQ(ValidateEmbeddingRequest({"clip", {}}).code(), absl::StatusCode::kInvalidArgument);
  const absl::Status s = ValidateEmbeddingRequest({"clip", {"a", ""}});
  EXPECT_NE(s.message().find("texts[1]"), std::string::npos);
}

}  // namespace
}  // namespace semnav::modelproxy
