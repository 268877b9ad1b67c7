#include "services/common/lexicon/canonical_term.h"

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "absl/strings/str_split.h"

namespace semnav {
namespace {

// Surface phrase -> canonical name (COCO class or room name as spelled in ConceptNet).
constexpr std::pair<const char*, const char*> kSynonyms[] = {
    {"sofa", "couch"},
    {"settee", "couch"},
    {"television", "tv"},
    {"tv monitor", "tv"},
    {"monitor", "tv"},
    {"fridge", "refrigerator"},
    {"mobile phone", "cell phone"},
    {"cellphone", "cell phone"},
    {"phone", "cell phone"},
    {"smartphone", "cell phone"},
    {"mug", "cup"},
    {"table", "dining table"},
    {"dinner table", "dining table"},
    {"plant", "potted plant"},
    {"houseplant", "potted plant"},
    {"notebook computer", "laptop"},
    {"computer mouse", "mouse"},
    {"remote control", "remote"},
    {"motorbike", "motorcycle"},
    {"bike", "bicycle"},
    {"plane", "airplane"},
    {"aeroplane", "airplane"},
    {"hair dryer", "hair drier"},
    {"hairdryer", "hair drier"},
    {"puppy", "dog"},
    {"kitten", "cat"},
    {"man", "person"},
    {"woman", "person"},
    {"people", "person"},
    {"purse", "handbag"},
    {"doughnut", "donut"},
    {"basin", "sink"},
    {"washbasin", "sink"},
    {"stove", "oven"},
    {"cooker", "oven"},
    {"microwave oven", "microwave"},
    {"livingroom", "living room"},
    {"lounge", "living room"},
    {"sitting room", "living room"},
    {"restroom", "bathroom"},
    {"washroom", "bathroom"},
    {"lavatory", "bathroom"},
    {"wc", "bathroom"},
    {"bath room", "bathroom"},
    {"study", "office"},
    {"cellar", "basement"},
    {"dining area", "dining room"},
    // Identity entries keep these phrases whole (else "table" would become "dining table").
    {"coffee table", "coffee table"},
    {"bedside table", "bedside table"},
    // Chinese names (matched as substrings: Chinese text has no spaces).
    {"笔记本电脑", "laptop"},
    {"卫生间", "bathroom"},
    {"洗手间", "bathroom"},
    {"微波炉", "microwave"},
    {"椅子", "chair"},
    {"沙发", "couch"},
    {"电视", "tv"},
    {"冰箱", "refrigerator"},
    {"马桶", "toilet"},
    {"杯子", "cup"},
    {"瓶子", "bottle"},
    {"键盘", "keyboard"},
    {"鼠标", "mouse"},
    {"手机", "cell phone"},
    {"时钟", "clock"},
    {"花瓶", "vase"},
    {"水槽", "sink"},
    {"烤箱", "oven"},
    {"餐桌", "dining table"},
    {"盆栽", "potted plant"},
    {"背包", "backpack"},
    {"雨伞", "umbrella"},
    {"剪刀", "scissors"},
    {"牙刷", "toothbrush"},
    {"书架", "bookshelf"},
    {"书房", "office"},
    {"书", "book"},
    {"床", "bed"},
    {"厨房", "kitchen"},
    {"卧室", "bedroom"},
    {"浴室", "bathroom"},
    {"客厅", "living room"},
    {"办公室", "office"},
    {"车库", "garage"},
    {"行人", "person"},
};

std::string Singular(const std::string& word) {
  auto ends = [&](const char* suffix) { return absl::EndsWith(word, suffix); };
  if (word.size() <= 3 || !ends("s") || ends("ss") || ends("us") || ends("is")) return word;
  const std::string stem = word.substr(0, word.size() - 1);
  if (ends("ies")) return word.substr(0, word.size() - 3) + "y";
  if (ends("lves")) return word.substr(0, word.size() - 3) + "f";
  if (ends("ives")) return word.substr(0, word.size() - 3) + "fe";
  if (ends("sses") || ends("xes") || ends("ches") || ends("shes")) {
    return word.substr(0, word.size() - 2);
  }
  return stem;
}

// Lower-case words with separators unified, articles dropped, each word singular.
std::vector<std::string> NormalizedWords(absl::string_view phrase) {
  std::string text;
  for (char c : phrase) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x80 || absl::ascii_isalnum(u)) {
      text.push_back(static_cast<char>(absl::ascii_tolower(u)));
    } else if (c != '\'') {
      text.push_back(' ');
    }
  }
  std::vector<std::string> words;
  for (absl::string_view w : absl::StrSplit(text, ' ', absl::SkipEmpty())) {
    if (words.empty() && (w == "a" || w == "an" || w == "the")) continue;
    words.push_back(Singular(std::string(w)));
  }
  return words;
}

struct SynonymTable {
  std::map<std::string, std::string> ascii;                  // normalized phrase -> canonical
  std::vector<std::pair<std::string, std::string>> chinese;  // substring -> canonical
};

const SynonymTable& Synonyms() {
  static const SynonymTable* table = [] {
    auto* t = new SynonymTable;
    for (const auto& [surface, canonical] : kSynonyms) {
      const std::string target = absl::StrJoin(NormalizedWords(canonical), " ");
      // Canonical names map to themselves first, so "dining table" never becomes
      // "dining dining table" through the "table" entry.
      t->ascii.emplace(target, target);
      if (static_cast<unsigned char>(surface[0]) >= 0x80) {
        t->chinese.emplace_back(surface, target);
      } else {
        t->ascii.emplace(absl::StrJoin(NormalizedWords(surface), " "), target);
      }
    }
    // Longest Chinese names first so "笔记本电脑" wins over "书".
    std::stable_sort(t->chinese.begin(), t->chinese.end(),
                     [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
    return t;
  }();
  return *table;
}

std::string LookupAscii(const std::string& phrase) {
  auto it = Synonyms().ascii.find(phrase);
  return it == Synonyms().ascii.end() ? "" : it->second;
}

}  // namespace

std::string CanonicalTerm(absl::string_view phrase) {
  std::string spaced(phrase);
  for (const auto& [surface, canonical] : Synonyms().chinese) {
    spaced = absl::StrReplaceAll(spaced, {{surface, " " + canonical + " "}});
  }
  const std::vector<std::string> words = NormalizedWords(spaced);
  std::vector<std::string> out;
  for (size_t i = 0; i < words.size();) {
    size_t used = 0;
    for (size_t n = std::min<size_t>(3, words.size() - i); n >= 1 && used == 0; --n) {
      const std::string candidate = absl::StrJoin(words.begin() + static_cast<long>(i),
                                                  words.begin() + static_cast<long>(i + n), " ");
      const std::string canonical = LookupAscii(candidate);
      if (!canonical.empty()) {
        out.push_back(canonical);
        used = n;
      }
    }
    if (used == 0) {
      out.push_back(words[i]);
      used = 1;
    }
    i += used;
  }
  return absl::StrJoin(out, " ");
}

}  // namespace semnav
