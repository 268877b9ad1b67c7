// Word segmentation for English and Chinese instructions with ICU's word break iterator, whose
// dictionary mode splits Chinese runs into words (seed 002, section 11.1 P0 item).
#pragma once

#include <unicode/uversion.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"

U_NAMESPACE_BEGIN
class BreakIterator;
U_NAMESPACE_END

namespace semnav::reasoning {

struct TextToken {
  std::string text;  // UTF-8; ASCII letters lower-cased.
  bool is_word;      // false for punctuation (clause separators such as "," or "，").
  bool is_cjk;       // the token is made of ideographs (joined to neighbours without a space).
};

class TextSegmenter {
 public:
  static absl::StatusOr<TextSegmenter> Create();
  TextSegmenter(TextSegmenter&&) noexcept;
  TextSegmenter& operator=(TextSegmenter&&) noexcept;
  ~TextSegmenter();

  // Tokens of `text` in order; whitespace is dropped. Not thread-safe (one per thread).
  std::vector<TextToken> Segment(std::string_view text);

 private:
  explicit TextSegmenter(std::unique_ptr<icu::BreakIterator> iterator);
  std::unique_ptr<icu::BreakIterator> iterator_;
};

}  // namespace semnav::reasoning
