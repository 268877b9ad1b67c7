#include "services/relocalization/core/landmark_matcher.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "services/relocalization/core/hungarian.h"

namespace semnav::relocalization {
namespace {

SimilarityTerms TermsWithoutPosition(const IndexedLandmarks& a, size_t i, const IndexedLandmarks& b,
                                     size_t j) {
  return {1.0, ScaleSimilarity(a.at(i).scale, b.at(j).scale),
          std::max(0.0, b.DescriptorSimilarity(j, a.unit_descriptor(i)))};
}

}  // namespace

NeighbourhoodMatcher::NeighbourhoodMatcher(const IndexedLandmarks& query,
                                           const IndexedLandmarks& map, const MatchParams& params)
    : query_(query),
      map_(map),
      params_(params),
      candidates_(query.size()),
      map_used_(map.size(), false) {
  std::vector<double> best(query.size(), 0.0);
  for (size_t q = 0; q < query.size(); ++q) {
    const size_t labels = std::max<size_t>(1, params.retrieval_labels);
    // Each map landmark sits in one bucket, so distinct labels never repeat a candidate.
    for (int label : TopDescriptorLabels(query.at(q).descriptor, labels)) {
      for (size_t m : map.WithLabel(label)) {
        candidates_[q].push_back({m, map.DescriptorSimilarity(m, query.unit_descriptor(q))});
      }
    }
    auto& c = candidates_[q];
    const size_t keep = std::min(c.size(), params.max_candidates);
    std::partial_sort(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(keep), c.end(),
                      [](const Candidate& a, const Candidate& b) {
                        return a.desc > b.desc || (a.desc == b.desc && a.map < b.map);
                      });
    c.resize(keep);
    if (!c.empty()) best[q] = c.front().desc;
  }
  order_.resize(query.size());
  std::iota(order_.begin(), order_.end(), size_t{0});
  std::stable_sort(order_.begin(), order_.end(),
                   [&](size_t a, size_t b) { return best[a] > best[b]; });
}

double NeighbourhoodMatcher::NeighbourhoodScore(size_t query, const std::vector<size_t>& nq,
                                                const Candidate& candidate) const {
  const SimilarityParams& sp = params_.similarity;
  const double anchor =
      CombinedSimilarity(TermsWithoutPosition(query_, query, map_, candidate.map), sp);
  if (anchor <= 0.0) return 0.0;
  const std::vector<size_t> nm = map_.Neighbourhood(candidate.map, params_.neighbourhood_size);
  const Eigen::Vector3d& qa = query_.at(query).position;
  const Eigen::Vector3d& ma = map_.at(candidate.map).position;
  // Before the pose is known only distances to the anchor are comparable.
  Eigen::MatrixXd s(static_cast<Eigen::Index>(nq.size()), static_cast<Eigen::Index>(nm.size()));
  // Both centres' uncertainties add up in the distance between them.
  const double anchor_tolerance =
      ScaleTolerance(sp, query_.at(query).scale, map_.at(candidate.map).scale);
  for (size_t i = 0; i < nq.size(); ++i) {
    const double dq = (query_.at(nq[i]).position - qa).norm();
    for (size_t j = 0; j < nm.size(); ++j) {
      SimilarityTerms terms = TermsWithoutPosition(query_, nq[i], map_, nm[j]);
      const double tolerance = ScaleTolerance(sp, query_.at(nq[i]).scale, map_.at(nm[j]).scale);
      const double sigma = sp.pos_sigma_per_scale > 0.0
                               ? sp.pos_sigma_m * std::sqrt(anchor_tolerance * anchor_tolerance +
                                                            tolerance * tolerance - 1.0)
                               : sp.pos_sigma_m;
      terms.pos = PositionSimilarity(dq - (map_.at(nm[j]).position - ma).norm(), sigma);
      s(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = CombinedSimilarity(terms, sp);
    }
  }
  const std::vector<int> assignment = MaxSimilarityAssignment(s);
  double total = anchor;
  size_t paired = 0;
  for (size_t i = 0; i < assignment.size(); ++i) {
    if (assignment[i] < 0) continue;
    total += s(static_cast<Eigen::Index>(i), assignment[i]);
    ++paired;
  }
  return paired >= params_.min_neighbour_matches ? total : 0.0;
}

std::vector<Match> NeighbourhoodMatcher::Next(size_t count) {
  std::vector<Match> found;
  while (found.size() < count && !exhausted()) {
    const size_t q = order_[cursor_++];
    Match best{q, 0, 0.0};
    const std::vector<size_t> nq = query_.Neighbourhood(q, params_.neighbourhood_size);
    for (const Candidate& c : candidates_[q]) {
      if (map_used_[c.map]) continue;
      const double score = NeighbourhoodScore(q, nq, c);
      if (score > best.similarity) best = {q, c.map, score};
    }
    if (best.similarity <= 0.0) continue;
    map_used_[best.map] = true;
    found.push_back(best);
  }
  return found;
}

std::vector<Match> MatchUnderPose(const IndexedLandmarks& query, const IndexedLandmarks& map,
                                  const Eigen::Isometry3d& map_from_query,
                                  const MatchParams& params) {
  // Candidate pairs within the radius, scored by the full seed similarity.
  struct Edge {
    size_t query, map;
    double s;
  };
  std::vector<Edge> edges;
  for (size_t q = 0; q < query.size(); ++q) {
    const Eigen::Vector3d x = map_from_query * query.at(q).position;
    const SimilarityParams& sp = params.similarity;
    const double search_radius =
        params.rematch_radius_m * ScaleTolerance(sp, query.at(q).scale, query.at(q).scale);
    for (size_t m : map.tree().WithinRadius(x, search_radius)) {
      const double tolerance = ScaleTolerance(sp, query.at(q).scale, map.at(m).scale);
      const double error = (map.at(m).position - x).norm();
      if (error > params.rematch_radius_m * tolerance) continue;
      SimilarityTerms terms = TermsWithoutPosition(query, q, map, m);
      terms.pos = PositionSimilarity(error, sp.pos_sigma_m * tolerance);
      const double s = CombinedSimilarity(terms, params.similarity);
      if (s > 0.0) edges.push_back({q, m, s});
    }
  }
  // Connected groups of the bipartite candidate graph (union-find; map nodes offset).
  std::vector<size_t> parent(query.size() + map.size());
  std::iota(parent.begin(), parent.end(), size_t{0});
  auto find = [&](size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Edge& e : edges) parent[find(e.query)] = find(query.size() + e.map);
  std::vector<std::vector<size_t>> groups(parent.size());
  for (size_t i = 0; i < edges.size(); ++i) groups[find(edges[i].query)].push_back(i);

  std::vector<Match> matches;
  for (const std::vector<size_t>& group : groups) {
    if (group.empty()) continue;
    std::vector<size_t> rows, cols;
    for (size_t e : group) {
      rows.push_back(edges[e].query);
      cols.push_back(edges[e].map);
    }
    for (auto* v : {&rows, &cols}) {
      std::sort(v->begin(), v->end());
      v->erase(std::unique(v->begin(), v->end()), v->end());
    }
    auto index_of = [](const std::vector<size_t>& v, size_t x) {
      return static_cast<Eigen::Index>(std::lower_bound(v.begin(), v.end(), x) - v.begin());
    };
    Eigen::MatrixXd s = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()),
                                              static_cast<Eigen::Index>(cols.size()));
    for (size_t e : group)
      s(index_of(rows, edges[e].query), index_of(cols, edges[e].map)) = edges[e].s;
    const std::vector<int> assignment = MaxSimilarityAssignment(s);
    for (size_t r = 0; r < rows.size(); ++r) {
      if (assignment[r] < 0) continue;
      matches.push_back({rows[r], cols[static_cast<size_t>(assignment[r])],
                         s(static_cast<Eigen::Index>(r), assignment[r])});
    }
  }
  std::sort(matches.begin(), matches.end(),
            [](const Match& a, const Match& b) { return a.query < b.query; });
  return matches;
}

}  // namespace semnav::relocalization
