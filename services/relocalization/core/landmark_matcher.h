#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "services/relocalization/core/indexed_landmarks.h"
#include "services/relocalization/core/similarity.h"

namespace semnav::relocalization {

// Retrieval and matching parameters (seed 001, 3.1).
struct MatchParams {
  SimilarityParams similarity;
  size_t neighbourhood_size = 8;  // |N(P)|: nearest landmarks compared around each point
  size_t max_candidates = 16;     // hash candidates tried per query, best descriptor first
  // Hash buckets looked up per query landmark: its `retrieval_labels` most similar labels.
  // The seed uses 1 (the arg-max only); smoke often swaps the top two labels, so the
  // default also looks up the runner-up labels (docs/algorithms/relocalization.md, 3.1).
  size_t retrieval_labels = 3;
  size_t min_neighbour_matches = 3;  // neighbour pairs the Hungarian step must find
  size_t early_stop_matches = 6;     // m: stop retrieval after this many matches
  double rematch_radius_m = 0.5;     // search radius around each re-projected query landmark
};

// A query landmark paired with a map landmark.
struct Match {
  size_t query = 0;
  size_t map = 0;
  double similarity = 0.0;  // s of the pair (stage 1: anchor + neighbourhood score)
};

// Stage 1: candidates from the label hash (the buckets of the query's retrieval_labels most
// similar labels), neighbourhood-to-neighbourhood similarity solved with the Hungarian
// algorithm, best candidate wins. Query landmarks are visited by descending best
// descriptor similarity; each map landmark is matched at most once.
class NeighbourhoodMatcher {
 public:
  NeighbourhoodMatcher(const IndexedLandmarks& query, const IndexedLandmarks& map,
                       const MatchParams& params);

  // Matches further query landmarks until `count` new matches are found (early stop)
  // or every query landmark has been tried.
  std::vector<Match> Next(size_t count);
  bool exhausted() const { return cursor_ >= order_.size(); }

 private:
  struct Candidate {
    size_t map;
    double desc;  // descriptor similarity to the query landmark
  };
  // Summed similarity of the anchor pair and its Hungarian-matched neighbourhoods;
  // 0 when the anchor terms fail their thresholds or too few neighbours pair up.
  // `query_neighbours` is N(query), computed once per query landmark.
  double NeighbourhoodScore(size_t query, const std::vector<size_t>& query_neighbours,
                            const Candidate& candidate) const;

  const IndexedLandmarks& query_;
  const IndexedLandmarks& map_;
  MatchParams params_;
  std::vector<std::vector<Candidate>> candidates_;  // per query, best descriptor first
  std::vector<size_t> order_;
  size_t cursor_ = 0;
  std::vector<bool> map_used_;
};

// Stage 2: every query landmark moved by `map_from_query`, paired with map landmarks
// within rematch_radius_m by s (position term from the residual distance); each
// connected group of candidate pairs is solved with the Hungarian algorithm.
std::vector<Match> MatchUnderPose(const IndexedLandmarks& query, const IndexedLandmarks& map,
                                  const Eigen::Isometry3d& map_from_query,
                                  const MatchParams& params);

}  // namespace semnav::relocalization
