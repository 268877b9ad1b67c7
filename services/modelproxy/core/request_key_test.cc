#include "services/modelproxy/core/request_key.h"

#include <gtest/gtest.h>

namespace semnav::modelproxy {
namespace {

CompletionRequest TextRequest(const std::string& text) {
  CompletionRequest r;
  r.alias = "default";
  r.messages = {ChatMessage{Role::kUser, {ContentPart{text, "", ""}}}};
  return r;
}

TEST(ModelProxyRequestKeyTest, Sha256MatchesTheFipsTestVector) {
  EXPECT_EQ(Sha256Hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

TEST(ModelProxyRequestKeyTest, WhitespaceAndSchemaKeyOrderDoNotChangeTheKey) {
  EXPECT_EQ(RequestKey(TextRequest("find  the\n chair ")),
            RequestKey(TextRequest("find the chair")));
  EXPECT_NE(RequestKey(TextRequest("find the chair")), RequestKey(TextRequest("find the chairs")));
  CompletionRequest a = TextRequest("x"), b = TextRequest("x");
  a.format = b.format = ResponseFormat::kJsonSchema;
  a.json_schema = R"({"type":"object","required":["a"]})";
  b.json_schema = R"({ "required": ["a"], "type": "object" })";
  EXPECT_EQ(RequestKey(a), RequestKey(b));
  b.temperature = 0.5;
  EXPECT_NE(RequestKey(a), RequestKey(b));
}

TEST(ModelProxyRequestKeyTest, ImagesAreHashedNotCopied) {
  CompletionRequest a = TextRequest("what is this");
  a.messages[0].parts.push_back(ContentPart{"", "RAWPIXELBYTES", "image/png"});
  const std::string normalized = NormalizedRequest(a);
  EXPECT_EQ(normalized.find("RAWPIXELBYTES"), std::string::npos);
  EXPECT_NE(normalized.find(Sha256Hex("RAWPIXELBYTES")), std::string::npos);
  CompletionRequest b = a;
  b.messages[0].parts[1].image_data = "OTHERBYTES";
  EXPECT_NE(RequestKey(a), RequestKey(b));
}

}  // namespace
}  // namespace semnav::modelproxy
