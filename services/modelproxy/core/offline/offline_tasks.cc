#include "services/modelproxy/core/offline/offline_tasks.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "services/common/lexicon/canonical_term.h"
#include "services/modelproxy/core/offline/offline_decompose.h"

namespace semnav::modelproxy::offline {
namespace {

struct Scored {
  std::string id;
  double score = 0.0;
  std::string reason = "no lexical or commonsense evidence";
};

// The target as the prior knows it: its longest known word suffix ("red cup" -> "cup"), so
// attributes do not hide the object from the prior; the whole target if none is known.
std::string PriorName(const std::string& target, const PlacePrior& prior) {
  const std::vector<std::string> words = Words(target);
  for (size_t i = 0; i < words.size(); ++i) {
    const std::string suffix =
        absl::StrJoin(words.begin() + static_cast<long>(i), words.end(), " ");
    if (prior.Knows(suffix)) return suffix;
  }
  return target;
}

struct Target {
  std::string canonical;            // for lexical matching
  std::string prior_name;           // for the place prior
  std::optional<StandIn> stand_in;  // open vocabulary: only for targets the prior does not know
};

// Keeps the larger score and its reason.
void Consider(Scored& item, double score, const std::string& reason) {
  if (score > item.score) {
    item.score = score;
    item.reason = reason;
  }
}

absl::StatusOr<std::string> RequiredString(const nlohmann::json& object, const std::string& field,
                                           const std::string& path) {
  auto it = object.find(field);
  if (it == object.end() || !it->is_string() || it->get<std::string>().empty()) {
    return absl::InvalidArgumentError(absl::StrCat(path, field, " must be a non-empty string"));
  }
  return it->get<std::string>();
}

std::string OptionalString(const nlohmann::json& object, const char* field) {
  auto it = object.find(field);
  return it != object.end() && it->is_string() ? it->get<std::string>() : "";
}

absl::StatusOr<const nlohmann::json*> ItemList(const nlohmann::json& task, const char* field,
                                               const OfflineParams& params) {
  auto it = task.find(field);
  if (it == task.end() || !it->is_array() || it->empty() || it->size() > params.max_items) {
    return absl::InvalidArgumentError(
        absl::StrCat(field, " must be a list of 1..", params.max_items, " objects"));
  }
  std::set<std::string> ids;
  for (size_t i = 0; i < it->size(); ++i) {
    const std::string path = absl::StrCat(field, "[", i, "].");
    if (!(*it)[i].is_object())
      return absl::InvalidArgumentError(absl::StrCat(field, "[", i, "] must be an object"));
    absl::StatusOr<std::string> id = RequiredString((*it)[i], "id", path);
    if (!id.ok()) return id.status();
    if (!ids.insert(*id).second)
      return absl::InvalidArgumentError(absl::StrCat(path, "id '", *id, "' repeats"));
  }
  return &*it;
}

void ScoreDescription(Scored& item, const Target& target, const std::string& description,
                      const OfflineParams& params) {
  if (description.empty()) return;
  const double s =
      std::min(params.description_cap,
               LexicalMatch(target.canonical, CanonicalTerm(description), params.lexical));
  Consider(item, s, absl::StrFormat("description mentions the target (%.2f)", s));
}

// Label evidence: same/similar name, else objects found in the same places.
void ScoreLabel(Scored& item, const Target& target, const std::string& label,
                const PlacePrior& prior, const OfflineParams& params) {
  const double lexical = LexicalMatch(target.canonical, label, params.lexical);
  Consider(item, lexical,
           absl::StrFormat("label '%s' names the target (lexical %.2f)", label, lexical));
  const double related = params.relatedness_weight * prior.Relatedness(target.prior_name, label);
  Consider(
      item, related,
      absl::StrFormat("'%s' is found in the same places as the target (%.2f)", label, related));
  if (!target.stand_in) return;
  const StandIn& stand_in = *target.stand_in;
  if (!stand_in.known_class.empty()) {
    const double s = params.stand_in_class_weight *
                     LexicalMatch(CanonicalTerm(stand_in.known_class), label, params.lexical);
    Consider(item, s,
             absl::StrFormat("open vocabulary: a '%s' is seen as a '%s' (%.2f)", stand_in.phrase,
                             stand_in.known_class, s));
  }
  if (!stand_in.place.empty()) {
    const double s = params.stand_in_place_weight * prior.Affinity(label, stand_in.place);
    Consider(
        item, s,
        absl::StrFormat("open vocabulary: '%s' is typical of the %s, where a '%s' is kept (%.2f)",
                        label, stand_in.place, stand_in.phrase, s));
  }
}

Scored ScoreCandidate(const nlohmann::json& c, const Target& target, const PlacePrior& prior,
                      const OfflineParams& params) {
  Scored item{c["id"].get<std::string>()};
  ScoreLabel(item, target, CanonicalTerm(OptionalString(c, "label")), prior, params);
  ScoreDescription(item, target, OptionalString(c, "description"), params);
  return item;
}

Scored ScoreRegion(const nlohmann::json& r, const Target& target, const PlacePrior& prior,
                   const OfflineParams& params) {
  Scored item{r["id"].get<std::string>()};
  // The region's name against every place the target is found at: "bathroom" matches the
  // ConceptNet place "bathroom" fully and "bathroom cabinet" as a more specific place.
  const std::string name = CanonicalTerm(OptionalString(r, "name"));
  for (const auto& place_probability : prior.TopPlaces(target.prior_name, SIZE_MAX)) {
    const std::string& place = place_probability.first;
    const double s = params.place_weight * prior.Affinity(target.prior_name, place) *
                     LexicalMatch(name, place, params.lexical);
    Consider(item, s, absl::StrFormat("the target is typically at '%s' (%.2f)", place, s));
  }
  auto objects = r.find("objects");
  if (objects != r.end() && objects->is_array()) {
    for (const nlohmann::json& o : *objects) {
      if (o.is_string())
        ScoreLabel(item, target, CanonicalTerm(o.get<std::string>()), prior, params);
    }
  }
  if (target.stand_in && !target.stand_in->place.empty()) {
    const double s = params.place_weight *
                     LexicalMatch(name, CanonicalTerm(target.stand_in->place), params.lexical);
    Consider(item, s,
             absl::StrFormat("open vocabulary: a '%s' is kept in the %s (%.2f)",
                             target.stand_in->phrase, target.stand_in->place, s));
  }
  ScoreDescription(item, target, OptionalString(r, "description"), params);
  return item;
}

}  // namespace

absl::StatusOr<nlohmann::json> RunOfflineTask(const nlohmann::json& task, const PlacePrior& prior,
                                              const OfflineParams& params) {
  if (!task.is_object()) return absl::InvalidArgumentError("task must be a JSON object");
  absl::StatusOr<std::string> kind = RequiredString(task, "task", "");
  if (!kind.ok()) return kind.status();
  if (*kind == "decompose") return DecomposeOffline(task);
  absl::StatusOr<std::string> target_text = RequiredString(task, "target", "");
  if (!target_text.ok()) return target_text.status();
  Target target{CanonicalTerm(*target_text), "", std::nullopt};
  target.prior_name = PriorName(target.canonical, prior);
  if (!prior.Knows(target.prior_name)) target.stand_in = OpenVocabularyStandIn(*target_text);

  std::vector<Scored> ranking;
  if (*kind == "match_target") {
    absl::StatusOr<const nlohmann::json*> items = ItemList(task, "candidates", params);
    if (!items.ok()) return items.status();
    for (const nlohmann::json& c : **items)
      ranking.push_back(ScoreCandidate(c, target, prior, params));
  } else if (*kind == "rank_regions") {
    absl::StatusOr<const nlohmann::json*> items = ItemList(task, "regions", params);
    if (!items.ok()) return items.status();
    for (const nlohmann::json& r : **items)
      ranking.push_back(ScoreRegion(r, target, prior, params));
  } else {
    return absl::InvalidArgumentError(
        absl::StrCat("task '", *kind, "' is not one of match_target, rank_regions, decompose"));
  }
  std::stable_sort(ranking.begin(), ranking.end(),
                   [](const Scored& a, const Scored& b) { return a.score > b.score; });

  nlohmann::json items = nlohmann::json::array();
  for (const Scored& s : ranking) {
    items.push_back({{"id", s.id}, {"score", s.score}, {"reason", s.reason}});
  }
  const bool useful = ranking.front().score >= params.min_score;
  nlohmann::json open_vocabulary = nullptr;
  if (target.stand_in) {
    open_vocabulary = {{"phrase", target.stand_in->phrase},
                       {"known_class", target.stand_in->known_class},
                       {"place", target.stand_in->place}};
  }
  return nlohmann::json{{"task", *kind},
                        {"target", *target_text},
                        {"open_vocabulary", std::move(open_vocabulary)},
                        {"best_id", useful ? ranking.front().id : ""},
                        {"confidence", ranking.front().score},
                        {"target_in_prior", prior.Knows(target.prior_name)},
                        {"ranking", std::move(items)},
                        {"offline", true},
                        {"provenance", kPriorProvenance}};
}

}  // namespace semnav::modelproxy::offline
