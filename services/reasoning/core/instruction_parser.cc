#include "services/reasoning/core/instruction_parser.h"

#include <optional>

#include "services/common/lexicon/canonical_term.h"
#include "services/reasoning/core/phrase_matcher.h"

namespace semnav::reasoning {
namespace {

const LexiconEntry* EntryOfKind(const Phrase& phrase, TermKind kind) {
  for (const LexiconEntry* entry : phrase.entries) {
    if (entry->kind == kind) return entry;
  }
  return nullptr;
}

// Builds one clause from its phrases. Objects and relations are collected in order and
// paired afterwards, because the pairing direction depends on the language of the relation word.
class ClauseBuilder {
 public:
  void Add(const Phrase& phrase, const Phrase* next) {
    const LexiconEntry* object = EntryOfKind(phrase, TermKind::kObject);
    const LexiconEntry* colour = EntryOfKind(phrase, TermKind::kColour);
    const bool next_is_object = next != nullptr && EntryOfKind(*next, TermKind::kObject) != nullptr;
    if (colour != nullptr && (object == nullptr || next_is_object)) {
      pending_colours_.push_back(colour->canonical);
      pending_text_ += phrase.surface;
      return;
    }
    if (object != nullptr) {
      TargetSpec spec;
      spec.name = object->canonical;
      spec.colours = std::move(pending_colours_);
      spec.text = pending_text_ + (IsAscii(phrase.surface) && !pending_text_.empty() ? " " : "") +
                  phrase.surface;
      pending_colours_.clear();
      pending_text_.clear();
      items_.push_back({std::move(spec), "", false});
      return;
    }
    if (const LexiconEntry* room = EntryOfKind(phrase, TermKind::kRoom)) {
      clause_.room = TargetSpec{room->canonical, true, {}, "", "", phrase.surface};
    } else if (const LexiconEntry* relation = EntryOfKind(phrase, TermKind::kRelation)) {
      items_.push_back({TargetSpec{}, relation->canonical, IsAscii(phrase.surface)});
    } else if (const LexiconEntry* action = EntryOfKind(phrase, TermKind::kAction)) {
      clause_.actions.push_back(action->canonical);
    } else if (EntryOfKind(phrase, TermKind::kNegation) != nullptr) {
      clause_.negated = true;
    } else if (EntryOfKind(phrase, TermKind::kDeixis) != nullptr) {
      clause_.deictic = true;
    } else if (phrase.entries.empty()) {
      ++clause_.unknown_words;
    }
  }

  Clause Finish() {
    for (const std::string& colour : pending_colours_) clause_.loose_colours.push_back(colour);
    // Pair each relation with its neighbours: English "target REL anchor", Chinese "anchor REL
    // target".
    std::vector<bool> consumed(items_.size(), false);
    for (std::size_t i = 0; i < items_.size(); ++i) {
      if (items_[i].relation.empty()) continue;
      consumed[i] = true;
      const std::optional<std::size_t> before = Neighbour(i, -1, consumed);
      const std::optional<std::size_t> after = Neighbour(i, +1, consumed);
      std::optional<std::size_t> target = items_[i].english ? before : after;
      std::optional<std::size_t> anchor = items_[i].english ? after : before;
      if (!target.has_value()) std::swap(target, anchor);  // "去灭火器旁边": go beside it.
      if (!target.has_value()) continue;
      TargetSpec& spec = items_[*target].spec;
      spec.relation = items_[i].relation;
      if (anchor.has_value()) {
        spec.anchor = items_[*anchor].spec.name;
        consumed[*anchor] = true;
      }
    }
    for (std::size_t i = 0; i < items_.size(); ++i) {
      if (!consumed[i] && items_[i].relation.empty()) clause_.objects.push_back(items_[i].spec);
    }
    return std::move(clause_);
  }

 private:
  struct Item {
    TargetSpec spec;       // set for objects
    std::string relation;  // set for relation words
    bool english;          // relation word written in English
  };

  std::optional<std::size_t> Neighbour(std::size_t i, int step, const std::vector<bool>& consumed) {
    for (std::ptrdiff_t k = static_cast<std::ptrdiff_t>(i) + step;
         k >= 0 && k < static_cast<std::ptrdiff_t>(items_.size()); k += step) {
      const auto index = static_cast<std::size_t>(k);
      if (!items_[index].relation.empty()) return std::nullopt;
      if (!consumed[index]) return index;
    }
    return std::nullopt;
  }

  Clause clause_;
  std::vector<Item> items_;
  std::vector<std::string> pending_colours_;
  std::string pending_text_;
};

}  // namespace

int ParsedInstruction::unknown_words() const {
  int total = 0;
  for (const Clause& clause : clauses) total += clause.unknown_words;
  return total;
}

InstructionParser::InstructionParser(const Lexicon* lexicon, TextSegmenter segmenter)
    : lexicon_(lexicon), segmenter_(std::move(segmenter)) {}

ParsedInstruction InstructionParser::Parse(std::string_view instruction) {
  const std::vector<Phrase> phrases = MatchPhrases(segmenter_.Segment(instruction), *lexicon_);
  ParsedInstruction parsed;
  ClauseBuilder builder;
  bool clause_has_content = false;
  for (std::size_t i = 0; i < phrases.size(); ++i) {
    const Phrase& phrase = phrases[i];
    const LexiconEntry* action = EntryOfKind(phrase, TermKind::kAction);
    const bool is_then = action != nullptr && action->canonical == "then";
    if (phrase.is_separator || is_then) {
      if (clause_has_content) parsed.clauses.push_back(builder.Finish());
      builder = ClauseBuilder();
      clause_has_content = false;
      continue;
    }
    const Phrase* next = i + 1 < phrases.size() ? &phrases[i + 1] : nullptr;
    builder.Add(phrase, next);
    clause_has_content = true;
  }
  if (clause_has_content) parsed.clauses.push_back(builder.Finish());
  return parsed;
}

}  // namespace semnav::reasoning
