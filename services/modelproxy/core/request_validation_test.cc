#include "services/modelproxy/core/request_validation.h"

#include <gtest/gtest.h>

#include <limits>

#include "services/common/status/field_error.h"

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

// A minimal PNG header (signature + IHDR) declaring width x height.
std::string PngHeader(uint32_t width, uint32_t height) {
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (uint32_t v : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) {
      png.push_back(static_cast<char>((v >> shift) & 0xff));
    }
  }
  return png + std::string("\x08\x02\0\0\0", 5);
}

// A minimal JPEG: SOI, an APP0 segment to skip, then SOF0 declaring width x height.
std::string JpegHeader(uint32_t width, uint32_t height) {
  std::string jpeg("\xff\xd8\xff\xe0\0\x04\0\0\xff\xc0\0\x11\x08", 13);
  for (uint32_t v : {height, width}) {
    jpeg.push_back(static_cast<char>((v >> 8) & 0xff));
    jpeg.push_back(static_cast<char>(v & 0xff));
  }
  return jpeg + std::string("\x03\x01\x22\0", 4);
}

// The field ErrorInfo will carry (not a substring of the message).
void ExpectField(const absl::Status& s, const std::string& field) {
  EXPECT_EQ(s.code(), absl::StatusCode::kInvalidArgument) << field << ": " << s;
  EXPECT_EQ(ErrorField(s).value_or(""), field) << s;
  EXPECT_LT(s.message().size(), 1024u);
}

CompletionRequest WithImage(std::string data, std::string mime = "image/png") {
  CompletionRequest r = Good();
  r.messages[0].parts.push_back(ContentPart{"", std::move(data), std::move(mime)});
  return r;
}

TEST(ModelProxyRequestValidationTest, ReadsImageSizesFromPngAndJpegHeaders) {
  EXPECT_EQ(ImageDimensions(PngHeader(640, 480), "image/png"), std::make_pair(640u, 480u));
  EXPECT_EQ(ImageDimensions(JpegHeader(1280, 720), "image/jpeg"), std::make_pair(1280u, 720u));
  EXPECT_FALSE(ImageDimensions("rgb", "image/png").has_value());
  EXPECT_FALSE(ImageDimensions(PngHeader(1, 1), "image/jpeg").has_value());
}

TEST(ModelProxyRequestValidationTest, HostileValuesNameTheirField) {
  CompletionRequest r = Good();
  r.temperature = std::numeric_limits<double>::quiet_NaN();
  ExpectField(ValidateCompletionRequest(r), "temperature");
  r = Good();
  r.temperature = 1e300;
  ExpectField(ValidateCompletionRequest(r), "temperature");
  r = Good();
  r.max_tokens = std::numeric_limits<int>::max();
  ExpectField(ValidateCompletionRequest(r), "max_tokens");
  r = Good();
  r.alias = std::string(1 << 20, 'a');
  ExpectField(ValidateCompletionRequest(r), "model_alias");
  // The prompt budget is for all text: the part that crosses 256 KiB is named.
  r = Good();
  r.messages[0].parts.push_back(ContentPart{std::string(kMaxPromptTextBytes - 2, 't'), "", ""});
  EXPECT_TRUE(ValidateCompletionRequest(r).ok());
  r.messages[0].parts.push_back(ContentPart{"x", "", ""});
  ExpectField(ValidateCompletionRequest(r), "messages[0].parts[2].text");
  r = Good();
  r.messages[0].parts[0].text = std::string(1 << 20, 't');
  ExpectField(ValidateCompletionRequest(r), "messages[0].parts[0].text");
  r = Good();
  r.messages.resize(kMaxMessages + 1, r.messages[0]);
  ExpectField(ValidateCompletionRequest(r), "messages");
  r = Good();
  r.messages[0].parts.resize(kMaxPartsPerMessage + 1, r.messages[0].parts[0]);
  ExpectField(ValidateCompletionRequest(r), "messages[0].parts");
  r = Good();
  r.format = ResponseFormat::kJsonSchema;
  r.json_schema = "{\"a\":\"" + std::string(kMaxJsonSchemaBytes, 's') + "\"}";
  ExpectField(ValidateCompletionRequest(r), "json_schema");
}

TEST(ModelProxyRequestValidationTest, ImagesStayWithinTheByteAndPixelBudget) {
  EXPECT_TRUE(ValidateCompletionRequest(WithImage(PngHeader(8192, 8192))).ok());
  EXPECT_TRUE(ValidateCompletionRequest(WithImage(JpegHeader(640, 480), "image/jpeg")).ok());
  // A few bytes claiming a 100000 x 100000 raster (a decompression bomb for the vendor).
  ExpectField(ValidateCompletionRequest(WithImage(PngHeader(100000, 100000))),
              "messages[0].parts[1].image.data");
  ExpectField(ValidateCompletionRequest(WithImage(JpegHeader(8193, 2), "image/jpeg")),
              "messages[0].parts[1].image.data");
  ExpectField(ValidateCompletionRequest(WithImage("not a png")), "messages[0].parts[1].image.data");
  const std::string oversized = PngHeader(4, 4) + std::string(kMaxImageBytes, 0);
  ExpectField(ValidateCompletionRequest(WithImage(oversized)), "messages[0].parts[1].image.data");
  CompletionRequest many = Good();
  for (size_t i = 0; i <= kMaxImagesPerRequest; ++i) {
    many.messages[0].parts.push_back(ContentPart{"", PngHeader(4, 4), "image/png"});
  }
  ExpectField(ValidateCompletionRequest(many), "messages[0].parts[17].image");
}

TEST(ModelProxyRequestValidationTest, EmbeddingTextsAndAliasWithinLimits) {
  ExpectField(ValidateEmbeddingRequest({"clip", {std::string(kMaxEmbeddingTextBytes + 1, 'e')}}),
              "texts[0]");
  ExpectField(ValidateEmbeddingRequest({"clip", std::vector<std::string>(257, "a")}), "texts");
  ExpectField(ValidateEmbeddingRequest({std::string(300, 'a'), {"a chair"}}), "model_alias");
}

}  // namespace
}  // namespace semnav::modelproxy
