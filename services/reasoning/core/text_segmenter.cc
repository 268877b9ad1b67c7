#include "services/reasoning/core/text_segmenter.h"

#include <unicode/brkiter.h>
#include <unicode/uchar.h>
#include <unicode/unistr.h>

#include "absl/strings/str_cat.h"
#include "services/common/lexicon/lexicon.h"

namespace semnav::reasoning {

absl::StatusOr<TextSegmenter> TextSegmenter::Create() {
  UErrorCode status = U_ZERO_ERROR;
  std::unique_ptr<icu::BreakIterator> iterator(
      icu::BreakIterator::createWordInstance(icu::Locale::getRoot(), status));
  if (U_FAILURE(status) || iterator == nullptr) {
    return absl::InternalError(absl::StrCat("ICU word break iterator: ", u_errorName(status)));
  }
  return TextSegmenter(std::move(iterator));
}

TextSegmenter::TextSegmenter(std::unique_ptr<icu::BreakIterator> iterator)
    : iterator_(std::move(iterator)) {}
TextSegmenter::TextSegmenter(TextSegmenter&&) noexcept = default;
TextSegmenter& TextSegmenter::operator=(TextSegmenter&&) noexcept = default;
TextSegmenter::~TextSegmenter() = default;

std::vector<TextToken> TextSegmenter::Segment(std::string_view text) {
  std::vector<TextToken> tokens;
  const icu::UnicodeString unicode = icu::UnicodeString::fromUTF8(
      icu::StringPiece(text.data(), static_cast<int32_t>(text.size())));
  iterator_->setText(unicode);
  int32_t start = iterator_->first();
  for (int32_t end = iterator_->next(); end != icu::BreakIterator::DONE;
       start = end, end = iterator_->next()) {
    const icu::UnicodeString piece = unicode.tempSubStringBetween(start, end);
    const UChar32 first = piece.char32At(0);
    if (u_isUWhiteSpace(first)) continue;
    // UBRK_WORD_NONE marks spaces and punctuation; everything else is a word, number or ideograph.
    const bool is_word = iterator_->getRuleStatus() != UBRK_WORD_NONE;
    const bool is_cjk = u_hasBinaryProperty(first, UCHAR_IDEOGRAPHIC);
    std::string utf8;
    piece.toUTF8String(utf8);
    tokens.push_back({ToLowerAscii(utf8), is_word, is_cjk});
  }
  return tokens;
}

}  // namespace semnav::reasoning
