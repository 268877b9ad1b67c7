#include "services/modelproxy/core/offline/offline_decompose.h"

#include <algorithm>
#include <string>
#include <vector>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "absl/strings/str_split.h"
#include "absl/strings/string_view.h"
#include "absl/strings/strip.h"
#include "services/common/lexicon/canonical_term.h"

namespace semnav::modelproxy::offline {
namespace {

constexpr char kCut = '\x1f';  // clause boundary marker (never in text after normalisation)

struct Verb {
  absl::string_view phrase;  // English phrases end with a space: whole words only
  absl::string_view type;
};

// Longest phrases of a kind first where one is a prefix of another ("go back to" / "go to").
constexpr Verb kVerbs[] = {
    {"go back to ", "BACKTRACK"},
    {"return to ", "BACKTRACK"},
    {"回到", "BACKTRACK"},
    {"返回", "BACKTRACK"},
    {"look around", "LOOK_AROUND"},
    {"环顾四周", "LOOK_AROUND"},
    {"看看周围", "LOOK_AROUND"},
    {"四处看看", "LOOK_AROUND"},
    {"go near ", "APPROACH"},
    {"get close to ", "APPROACH"},
    {"approach ", "APPROACH"},
    {"靠近", "APPROACH"},
    {"接近", "APPROACH"},
    {"走近", "APPROACH"},
    {"go to ", "NAVIGATE"},
    {"go into ", "NAVIGATE"},
    {"navigate to ", "NAVIGATE"},
    {"head to ", "NAVIGATE"},
    {"walk to ", "NAVIGATE"},
    {"move to ", "NAVIGATE"},
    {"fly to ", "NAVIGATE"},
    {"enter ", "NAVIGATE"},
    {"前往", "NAVIGATE"},
    {"走到", "NAVIGATE"},
    {"进入", "NAVIGATE"},
    {"去", "NAVIGATE"},
    {"到", "NAVIGATE"},
    {"look for ", "FIND"},
    {"search for ", "FIND"},
    {"find ", "FIND"},
    {"locate ", "FIND"},
    {"寻找", "FIND"},
    {"找到", "FIND"},
    {"查找", "FIND"},
    {"搜索", "FIND"},
    {"找", "FIND"},
    {"verify ", "VERIFY"},
    {"check ", "VERIFY"},
    {"confirm ", "VERIFY"},
    {"确认", "VERIFY"},
    {"检查", "VERIFY"},
    {"explore", "EXPLORE"},
    {"探索", "EXPLORE"},
    {"wait", "WAIT"},
    {"等待", "WAIT"},
    {"等", "WAIT"},
};

// Words that start a clause without adding to it.
constexpr absl::string_view kFillers[] = {"please ", "first ", "then ", "and ", "also ", "请",
                                          "先",      "你",     "帮我",  "再",   "并"};

// Clause boundaries besides punctuation.
constexpr absl::string_view kSequenceWords[] = {
    " and then ", " then ", " after that ", " afterwards ", " and finally ",
    " finally ",  "然后",   "接着",         "之后",         "最后",
    "再"};

// English relation markers (target before, anchor after) and the gateway's relation names.
constexpr std::pair<absl::string_view, absl::string_view> kRelations[] = {
    {" to the left of ", "left_of"},
    {" to the right of ", "right_of"},
    {" left of ", "left_of"},
    {" right of ", "right_of"},
    {" next to ", "near"},
    {" near ", "near"},
    {" beside ", "near"},
    {" by ", "near"},
    {" on ", "on"},
    {" in ", "in"}};
// Chinese: "<anchor><marker><target>".
constexpr std::pair<absl::string_view, absl::string_view> kRelationsZh[] = {
    {"旁边的", "near"}, {"附近的", "near"}, {"左边的", "left_of"}, {"右边的", "right_of"},
    {"上面的", "on"},   {"上的", "on"},     {"里面的", "in"},      {"里的", "in"}};

constexpr std::pair<absl::string_view, absl::string_view> kColours[] = {
    {"粉红色", "pink"}, {"红色", "red"},    {"绿色", "green"}, {"蓝色", "blue"}, {"黄色", "yellow"},
    {"白色", "white"},  {"黑色", "black"},  {"棕色", "brown"}, {"灰色", "grey"}, {"橙色", "orange"},
    {"粉色", "pink"},   {"紫色", "purple"}, {"红", "red"},     {"绿", "green"},  {"蓝", "blue"},
    {"黄", "yellow"},   {"白", "white"},    {"黑", "black"}};
constexpr absl::string_view kColoursEn[] = {"red",   "green", "blue", "yellow", "white", "black",
                                            "brown", "grey",  "gray", "orange", "pink",  "purple"};

constexpr absl::string_view kArticles[] = {"the ",  "a ",   "an ",  "my ",  "some ", "that ",
                                           "this ", "一个", "那个", "这个", "的"};

std::string Trim(absl::string_view text) { return std::string(absl::StripAsciiWhitespace(text)); }

// Strips leading articles / fillers from `list` until none applies.
template <size_t N>
std::string StripLeading(std::string text, const absl::string_view (&list)[N]) {
  for (bool again = true; again;) {
    again = false;
    text = Trim(text);
    for (absl::string_view word : list) {
      if (absl::StartsWith(text, word)) {
        text.erase(0, word.size());
        again = true;
      }
    }
  }
  return text;
}

std::vector<std::string> Clauses(absl::string_view instruction) {
  std::string text = absl::StrCat(" ", absl::AsciiStrToLower(std::string(instruction)), " ");
  for (absl::string_view mark :
       {",", ";", ".", "!", "?", "\n", "，", "；", "。", "！", "？", "、"}) {
    absl::StrReplaceAll({{mark, std::string(1, kCut)}}, &text);
  }
  for (absl::string_view word : kSequenceWords) {
    absl::StrReplaceAll({{word, absl::StrCat(" ", std::string(1, kCut), " ")}}, &text);
  }
  std::vector<std::string> clauses;
  for (absl::string_view piece : absl::StrSplit(text, kCut)) {
    std::string clause = StripLeading(Trim(piece), kFillers);
    if (!clause.empty()) clauses.push_back(std::move(clause));
  }
  // English " and " joins two clauses only when a verb follows ("find the cup and bring ...").
  std::vector<std::string> split;
  for (const std::string& clause : clauses) {
    std::string rest = clause;
    for (size_t at = rest.find(" and "); at != std::string::npos; at = rest.find(" and ", at + 1)) {
      const std::string after = Trim(absl::string_view(rest).substr(at + 5));
      bool verb = false;
      for (const Verb& v : kVerbs) verb = verb || absl::StartsWith(after, v.phrase);
      if (!verb) continue;
      split.push_back(Trim(absl::string_view(rest).substr(0, at)));
      rest = after;
      at = 0;
    }
    split.push_back(rest);
  }
  return split;
}

// "wait 5 seconds" / "等3秒" / "wait 2 minutes": seconds, 0 when none is said.
double Duration(const std::string& clause) {
  size_t start = clause.find_first_of("0123456789");
  if (start == std::string::npos) return 0.0;
  size_t end = clause.find_first_not_of("0123456789.", start);
  const double value = std::stod(clause.substr(start, end - start));
  const std::string unit =
      end == std::string::npos ? "" : Trim(absl::string_view(clause).substr(end));
  const bool minutes = absl::StartsWith(unit, "min") || absl::StartsWith(unit, "分");
  return std::min(value * (minutes ? 60.0 : 1.0), 3600.0);
}

// Canonical English where the offline lexicon knows the phrase; as said otherwise.
std::string Name(std::string phrase) {
  phrase = StripLeading(std::move(phrase), kArticles);
  while (absl::EndsWith(phrase, "的"))
    phrase.resize(phrase.size() - absl::string_view("的").size());
  const std::string canonical = CanonicalTerm(phrase);
  return canonical.empty() ? Trim(phrase) : canonical;
}

void ReadTarget(std::string phrase, nlohmann::json& subgoal) {
  phrase = absl::StrCat(" ", phrase, " ");
  for (const auto& [marker, relation] : kRelations) {
    const size_t at = phrase.find(marker.data(), 0, marker.size());
    if (at == std::string::npos || at == 0) continue;
    subgoal["relation"] = relation;
    subgoal["anchor"] = Name(phrase.substr(at + marker.size()));
    phrase = phrase.substr(0, at);
    break;
  }
  for (const auto& [marker, relation] : kRelationsZh) {
    const size_t at = phrase.find(marker.data(), 0, marker.size());
    if (at == std::string::npos || subgoal.contains("relation")) continue;
    subgoal["relation"] = relation;
    subgoal["anchor"] = Name(phrase.substr(0, at));
    phrase = phrase.substr(at + marker.size());
    break;
  }
  nlohmann::json colours = nlohmann::json::array();
  std::vector<std::string> kept;
  for (absl::string_view word : absl::StrSplit(phrase, ' ', absl::SkipEmpty())) {
    bool colour = false;
    for (absl::string_view name : kColoursEn) {
      if (word == name) {
        colours.push_back(name == "gray" ? "grey" : std::string(name));
        colour = true;
      }
    }
    if (!colour) kept.emplace_back(word);
  }
  phrase = absl::StrJoin(kept, " ");
  phrase = StripLeading(std::move(phrase), kArticles);
  for (const auto& [zh, en] : kColours) {  // Chinese colours lead the noun: "红色的杯子", "红杯子"
    if (!absl::StartsWith(phrase, zh)) continue;
    const std::string rest = StripLeading(phrase.substr(zh.size()), kArticles);
    if (rest.empty()) continue;  // "红" alone is no colour of a thing
    colours.push_back(en);
    phrase = rest;
    break;
  }
  if (!colours.empty()) subgoal["colours"] = colours;
  const std::string name = Name(phrase);
  if (!name.empty()) subgoal["target"] = name;
}

}  // namespace

absl::StatusOr<nlohmann::json> DecomposeOffline(const nlohmann::json& task) {
  const auto it = task.find("instruction");
  if (it == task.end() || !it->is_string() || it->get<std::string>().empty()) {
    return absl::InvalidArgumentError("instruction must be a non-empty string");
  }
  const std::string instruction = it->get<std::string>();
  if (instruction.size() > kMaxInstructionBytes) {
    return absl::InvalidArgumentError(
        absl::StrCat("instruction must be at most ", kMaxInstructionBytes, " bytes"));
  }
  nlohmann::json subgoals = nlohmann::json::array();
  for (const std::string& clause : Clauses(instruction)) {
    const Verb* verb = nullptr;
    for (const Verb& v : kVerbs) {
      if (absl::StartsWith(clause, v.phrase)) {
        verb = &v;
        break;
      }
    }
    if (verb == nullptr) continue;  // no action: nothing the robot can do with it
    nlohmann::json subgoal = {{"type", verb->type},
                              {"reason", absl::StrCat("offline rules: \"", clause, "\"")}};
    const std::string rest = Trim(absl::string_view(clause).substr(verb->phrase.size()));
    if (verb->type == "WAIT") {
      subgoal["duration_s"] = Duration(rest);
    } else if (verb->type != "LOOK_AROUND" && verb->type != "EXPLORE") {
      ReadTarget(rest, subgoal);
      if (!subgoal.contains("target")) continue;  // "go to" with nothing after it
    }
    subgoals.push_back(std::move(subgoal));
    if (static_cast<int>(subgoals.size()) == kMaxOfflineSubgoals) break;
  }
  if (subgoals.empty()) {
    return absl::InvalidArgumentError(
        "instruction: no clause names an action the offline rules know");
  }
  return nlohmann::json{
      {"task", "decompose"},
      {"subgoals", std::move(subgoals)},
      {"offline", true},
      {"provenance", "offline rules: clause split, verb phrases, colours, relations"}};
}

}  // namespace semnav::modelproxy::offline
