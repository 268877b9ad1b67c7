#include "services/modelproxy/core/request_validation.h"

#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"

namespace semnav::modelproxy {
namespace {

bool SupportedMime(const std::string& mime) {
  return mime == "image/png" || mime == "image/jpeg" || mime == "image/webp";
}

uint32_t BigEndian(absl::string_view data, size_t offset, int bytes) {
  uint32_t value = 0;
  for (int i = 0; i < bytes; ++i) {
    value = (value << 8) | static_cast<unsigned char>(data[offset + i]);
  }
  return value;
}

std::optional<std::pair<uint32_t, uint32_t>> PngDimensions(absl::string_view data) {
  constexpr absl::string_view kSignature("\x89PNG\r\n\x1a\n", 8);
  // Signature, IHDR length and type, then width and height (big-endian).
  if (data.size() < 24 || data.substr(0, 8) != kSignature || data.substr(12, 4) != "IHDR") {
    return std::nullopt;
  }
  return std::make_pair(BigEndian(data, 16, 4), BigEndian(data, 20, 4));
}

std::optional<std::pair<uint32_t, uint32_t>> JpegDimensions(absl::string_view data) {
  if (data.size() < 4 || static_cast<unsigned char>(data[0]) != 0xFF ||
      static_cast<unsigned char>(data[1]) != 0xD8) {
    return std::nullopt;
  }
  size_t offset = 2;
  // Walk the marker segments up to the first start-of-frame (SOF0-SOF15 except DHT, JPG, DAC).
  while (offset + 4 <= data.size()) {
    if (static_cast<unsigned char>(data[offset]) != 0xFF) return std::nullopt;
    const unsigned char marker = static_cast<unsigned char>(data[offset + 1]);
    if (marker == 0xFF) {  // fill byte
      ++offset;
      continue;
    }
    const uint32_t length = BigEndian(data, offset + 2, 2);
    if (length < 2) return std::nullopt;
    const bool start_of_frame =
        marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (start_of_frame) {
      if (offset + 9 > data.size()) return std::nullopt;
      return std::make_pair(BigEndian(data, offset + 7, 2), BigEndian(data, offset + 5, 2));
    }
    if (marker == 0xDA || marker == 0xD9) return std::nullopt;  // scan or end before a frame
    offset += 2 + length;
  }
  return std::nullopt;
}

absl::Status ValidateImage(const ContentPart& part, const std::string& path) {
  if (!SupportedMime(part.image_mime)) {
    return InvalidField(path + ".image.mime_type",
                        absl::StrCat("'", Preview(part.image_mime),
                                     "' is not image/png, image/jpeg or image/webp"));
  }
  const std::string data_field = path + ".image.data";
  if (part.image_data.size() > kMaxImageBytes) {
    return InvalidField(data_field, absl::StrCat("is ", part.image_data.size(),
                                                 " bytes, more than ", kMaxImageBytes));
  }
  if (part.image_mime == "image/webp") return absl::OkStatus();  // byte budget only
  const auto size = ImageDimensions(part.image_data, part.image_mime);
  if (!size) {
    return InvalidField(data_field, absl::StrCat("is not a ", part.image_mime, " file"));
  }
  if (size->first == 0 || size->second == 0 || size->first > kMaxImageSidePixels ||
      size->second > kMaxImageSidePixels) {
    return InvalidField(data_field,
                        absl::StrCat("declares ", size->first, "x", size->second,
                                     " pixels; each side must be 1..", kMaxImageSidePixels));
  }
  return absl::OkStatus();
}

}  // namespace

std::optional<std::pair<uint32_t, uint32_t>> ImageDimensions(absl::string_view data,
                                                             absl::string_view mime) {
  if (mime == "image/png") return PngDimensions(data);
  if (mime == "image/jpeg") return JpegDimensions(data);
  return std::nullopt;
}

absl::Status ValidateAlias(absl::string_view alias) {
  return CheckLength(alias, "model_alias", kMaxAliasBytes);
}

absl::Status ValidateCompletionRequest(const CompletionRequest& request) {
  if (auto s = ValidateAlias(request.alias); !s.ok()) return s;
  if (request.messages.empty()) return InvalidField("messages", "must not be empty");
  if (auto s = CheckCount(request.messages.size(), "messages", kMaxMessages); !s.ok()) return s;
  bool has_user = false;
  size_t text_bytes = 0, image_bytes = 0, images = 0;
  for (size_t i = 0; i < request.messages.size(); ++i) {
    const ChatMessage& message = request.messages[i];
    has_user = has_user || message.role == Role::kUser;
    const std::string parts_field = absl::StrCat("messages[", i, "].parts");
    if (message.parts.empty()) return InvalidField(parts_field, "must not be empty");
    if (auto s = CheckCount(message.parts.size(), parts_field, kMaxPartsPerMessage); !s.ok()) {
      return s;
    }
    for (size_t j = 0; j < message.parts.size(); ++j) {
      const ContentPart& part = message.parts[j];
      const std::string path = absl::StrCat(parts_field, "[", j, "]");
      if (!part.is_image()) {
        if (!part.image_mime.empty()) {
          return InvalidField(path + ".image.data", "must not be empty");
        }
        if (part.text.empty()) return InvalidField(path + ".text", "must not be empty");
        // The budget is for the whole prompt; the part that crosses it is named.
        text_bytes += part.text.size();
        if (text_bytes > kMaxPromptTextBytes) {
          return InvalidField(path + ".text",
                              absl::StrCat("brings the prompt text to ", text_bytes,
                                           " bytes, more than ", kMaxPromptTextBytes));
        }
        continue;
      }
      if (auto s = ValidateImage(part, path); !s.ok()) return s;
      if (message.role != Role::kUser) {
        return InvalidField(path + ".image", "is only allowed in user messages");
      }
      image_bytes += part.image_data.size();
      if (++images > kMaxImagesPerRequest || image_bytes > kMaxImageBytes) {
        return InvalidField(path + ".image",
                            absl::StrCat("more than ", kMaxImagesPerRequest, " images or ",
                                         kMaxImageBytes, " image bytes in one request"));
      }
    }
  }
  if (!has_user) return InvalidField("messages", "must contain a user message");
  if (request.max_tokens < 0 || request.max_tokens > kMaxTokensLimit) {
    return InvalidField("max_tokens", absl::StrCat("must be in [0, ", kMaxTokensLimit, "]"));
  }
  if (auto s = CheckRange(request.temperature, "temperature", 0.0, kMaxTemperature); !s.ok()) {
    return s;
  }
  if (auto s = CheckLength(request.json_schema, "json_schema", kMaxJsonSchemaBytes); !s.ok()) {
    return s;
  }
  if (request.format == ResponseFormat::kJsonSchema) {
    if (!nlohmann::json::parse(request.json_schema, nullptr, false).is_object()) {
      return InvalidField("json_schema", "must be a JSON object with RESPONSE_FORMAT_JSON_SCHEMA");
    }
  } else if (!request.json_schema.empty()) {
    return InvalidField("json_schema", "is only allowed with RESPONSE_FORMAT_JSON_SCHEMA");
  }
  return absl::OkStatus();
}

absl::Status ValidateEmbeddingRequest(const EmbeddingRequest& request) {
  if (auto s = ValidateAlias(request.alias); !s.ok()) return s;
  if (request.texts.empty() || request.texts.size() > kMaxEmbeddingTexts) {
    return InvalidField("texts", absl::StrCat("must hold 1..", kMaxEmbeddingTexts, " strings, got ",
                                              request.texts.size()));
  }
  for (size_t i = 0; i < request.texts.size(); ++i) {
    const std::string field = absl::StrCat("texts[", i, "]");
    if (request.texts[i].empty()) return InvalidField(field, "must not be empty");
    if (auto s = CheckLength(request.texts[i], field, kMaxEmbeddingTextBytes); !s.ok()) return s;
  }
  return absl::OkStatus();
}

}  // namespace semnav::modelproxy
