#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "absl/status/statusor.h"
#include "services/relocalization/core/indexed_landmarks.h"
#include "services/relocalization/core/landmark_matcher.h"
#include "services/relocalization/core/pose_solver.h"

namespace semnav::relocalization {

// Alias check on repeated structure (an addition to the seed, docs/algorithms/
// relocalization.md 5.4): an inlier whose map landmark has a look-alike twin nearby (same
// label, near-identical descriptor) can be matched one shelf pitch off. When a stage-2
// answer has such inliers and >= 3 others, the pose is re-solved from the others alone,
// stage 2 is run again from there, and the better supported answer is kept.
struct TwinParams {
  double radius_m = 1.0;     // twin search radius (> the 0.6 m shelf pitch); 0 = check off
  double min_cosine = 0.95;  // same-label objects of one class: ~0.83; boxes of one kind: ~0.99
  // The re-solved pose closer than this to the stage-2 pose needs no second stage 2.
  double pose_tolerance_m = 0.1;
  double pose_tolerance_deg = 1.0;
};

// Parameters of one relocalization (seed 001, 3.1-3.2).
struct RelocalizationParams {
  MatchParams match;
  PoseParams pose;
  int rematch_rounds = 2;  // stage-2 re-match + solve rounds, each under the latest pose
  double reliable_translation_m = 1.0;  // final vs initial pose: max translation change
  double reliable_rotation_deg = 20.0;  // final vs initial pose: max rotation change
  size_t reliable_min_inliers = 12;     // fewer final inliers is never reliable
  // Additions to the seed (docs/algorithms/relocalization.md, sections 4-5); 0 turns each
  // of the three below off.
  // After each stage-2 solve, pairs whose residual exceeds this are dropped and the pose
  // re-refined: ~3.5 sigma of 5 cm per-axis landmark noise, while a box matched to its
  // shelf neighbour is off by the 0.6 m pitch.
  double final_residual_gate_m = 0.3;
  // Inlier RMS residual above this is never reliable: correct poses stay near the noise
  // floor (~0.09 m for 5 cm per axis), a pose bent by a few wrong pairs does not.
  double reliable_max_rms_m = 0.12;
  // The inliers' second principal spread (std. dev., query frame) must reach this: a
  // (near-)collinear set, e.g. one shelf row, leaves the rotation about the row free.
  double reliable_min_spread_m = 0.3;
  // Stage-1 hypotheses tried: when a hypothesis ends unreliable, retrieval continues with m
  // fresh matches for a new initial pose. The seed stops after the first (1).
  int max_hypotheses = 3;
  TwinParams twin;
};

// The method as it was before the consistency checks (the seed's method with this project's
// earlier settings): top-label retrieval, one hypothesis, no residual gate, reliability only
// by initial vs final pose (10 deg) and inlier count.
RelocalizationParams SeedMethodParams();

struct RelocalizationResult {
  Eigen::Isometry3d map_from_query = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d initial_map_from_query = Eigen::Isometry3d::Identity();  // from stage 1
  std::vector<Match> matches;   // stage-2 pairs the final pose was solved from
  std::vector<size_t> inliers;  // indices into `matches` kept by outlier rejection
  double rms_residual_m = 0.0;
  double inlier_spread_m = 0.0;  // second principal std. dev. of the inliers (query frame)
  // Inliers whose map landmark has no look-alike twin (all inliers when the check is off),
  // and their RMS residual.
  size_t distinctive_inliers = 0;
  double distinctive_rms_m = 0.0;
  // Final pose within the thresholds of the initial one, enough inliers, RMS residual (of
  // all inliers, and of the distinctive ones when >= 3) and spread within their bounds.
  bool reliable = false;
};

// Square root of the second-largest eigenvalue of the positions' covariance: 0 for
// collinear points, the smaller in-plane extent for a planar set.
double SecondPrincipalSpread(const std::vector<Eigen::Vector3d>& positions);

// Finds the pose of the query landmarks (e.g. a keyframe's, or robot B's whole map)
// in the map: stage-1 retrieval with early stop after m matches -> initial pose ->
// stage-2 re-match of all query landmarks under it -> pose (repeated rematch_rounds
// times, each round under the latest pose; pairs beyond final_residual_gate_m dropped) ->
// alias check (TwinParams: stage 2 again from the distinctive inliers' pose, the better
// supported answer kept) -> reliability check (against the initial pose, inlier count,
// residual of all and of the distinctive inliers, spread).
// If the first m matches are inconsistent, retrieval continues with m more; if a
// hypothesis ends unreliable, with m fresh matches for another one (max_hypotheses): the
// first reliable answer is returned, else the unreliable one with the most inliers.
// NOT_FOUND (with the reason) for fewer than 3 landmarks on either side or when no
// consistent set of matches exists.
absl::StatusOr<RelocalizationResult> Relocalize(const IndexedLandmarks& query,
                                                const IndexedLandmarks& map,
                                                const RelocalizationParams& params);

}  // namespace semnav::relocalization
