#include "services/common/place_prior/place_prior.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "absl/status/status.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "nlohmann/json.hpp"
#include "services/common/lexicon/canonical_term.h"

namespace semnav {
namespace {

// "/c/en/living_room/n" -> "living room" (canonical).
std::string TermName(const std::string& term) {
  std::string rest = absl::StartsWith(term, "/c/en/") ? term.substr(6) : term;
  rest = rest.substr(0, rest.find('/'));
  return CanonicalTerm(rest);
}

}  // namespace

std::string PlacePrior::DefaultDir() { return SEMNAV_PLACE_PRIOR_DIR; }

std::string PlacePrior::DefaultPath() { return absl::StrCat(DefaultDir(), "/", kPlacePriorFile); }

absl::StatusOr<PlacePrior> PlacePrior::Load(const std::string& json_path) {
  std::ifstream in(json_path);
  if (!in)
    return absl::NotFoundError(absl::StrCat("offline prior file ", json_path, " cannot be read"));
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json json = nlohmann::json::parse(text.str(), nullptr, false);
  if (!json.is_object()) {
    return absl::InvalidArgumentError(
        absl::StrCat("offline prior file ", json_path, " is not a JSON object"));
  }
  PlacePrior prior;
  for (const auto& [cls, edges] : json.items()) {
    if (!edges.is_array()) {
      return absl::InvalidArgumentError(
          absl::StrCat("offline prior entry '", cls, "' is not a list"));
    }
    std::map<std::string, double>& places = prior.places_[CanonicalTerm(cls)];
    for (const nlohmann::json& edge : edges) {
      const nlohmann::json& end =
          edge.is_object() ? edge.value("end", nlohmann::json()) : nlohmann::json();
      const nlohmann::json& weight =
          edge.is_object() ? edge.value("weight", nlohmann::json()) : nlohmann::json();
      if (!end.is_object() || !end.value("term", nlohmann::json()).is_string() ||
          !weight.is_number()) {
        return absl::InvalidArgumentError(
            absl::StrCat("offline prior entry '", cls, "' has a malformed edge"));
      }
      const std::string place = TermName(end["term"].get<std::string>());
      if (weight.get<double>() <= 0.0 || place.empty()) continue;  // e.g. the bare term "/c/en/a"
      places[place] += weight.get<double>();
      ++prior.edge_count_;
    }
    double total = 0.0;
    for (const auto& [place, w] : places) total += w;
    for (auto& [place, w] : places) w /= total;
  }
  return prior;
}

double PlacePrior::Probability(const std::string& object, const std::string& place) const {
  auto it = places_.find(object);
  if (it == places_.end()) return 0.0;
  auto p = it->second.find(place);
  return p == it->second.end() ? 0.0 : p->second;
}

double PlacePrior::Affinity(const std::string& object, const std::string& place) const {
  auto it = places_.find(object);
  if (it == places_.end() || it->second.empty()) return 0.0;
  double best = 0.0;
  for (const auto& [p, w] : it->second) best = std::max(best, w);
  return Probability(object, place) / best;
}

double PlacePrior::Relatedness(const std::string& a, const std::string& b) const {
  auto ia = places_.find(a);
  auto ib = places_.find(b);
  if (ia == places_.end() || ib == places_.end()) return 0.0;
  double dot = 0.0, na = 0.0, nb = 0.0;
  for (const auto& [place, w] : ia->second) {
    na += w * w;
    auto q = ib->second.find(place);
    if (q != ib->second.end()) dot += w * q->second;
  }
  for (const auto& [place, w] : ib->second) nb += w * w;
  if (na == 0.0 || nb == 0.0) return 0.0;
  return dot / std::sqrt(na * nb);
}

std::vector<std::pair<std::string, double>> PlacePrior::TopPlaces(const std::string& object,
                                                                  size_t k) const {
  std::vector<std::pair<std::string, double>> out;
  auto it = places_.find(object);
  if (it == places_.end()) return out;
  out.assign(it->second.begin(), it->second.end());
  std::stable_sort(out.begin(), out.end(),
                   [](const auto& x, const auto& y) { return x.second > y.second; });
  if (out.size() > k) out.resize(k);
  return out;
}

}  // namespace semnav
