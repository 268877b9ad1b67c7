#include "services/relocalization/core/relocalizer.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

#include "absl/strings/str_cat.h"

namespace semnav::relocalization {
namespace {

// ScaleTolerance of each pair of `pairs` (empty when the tolerance does not grow with scale).
std::vector<double> PairTolerances(const IndexedLandmarks& query, const IndexedLandmarks& map,
                                   const std::vector<Match>& pairs,
                                   const std::vector<size_t>& which,
                                   const SimilarityParams& similarity) {
  if (similarity.pos_sigma_per_scale <= 0.0) return {};
  std::vector<double> tolerance;
  for (size_t i : which) {
    tolerance.push_back(
        ScaleTolerance(similarity, query.at(pairs[i].query).scale, map.at(pairs[i].map).scale));
  }
  return tolerance;
}

std::vector<size_t> AllOf(size_t count) {
  std::vector<size_t> all(count);
  std::iota(all.begin(), all.end(), size_t{0});
  return all;
}

absl::StatusOr<PoseEstimate> SolveFromMatches(const IndexedLandmarks& query,
                                              const IndexedLandmarks& map,
                                              const std::vector<Match>& matches,
                                              const RelocalizationParams& params) {
  std::vector<Eigen::Vector3d> p, q;
  for (const Match& m : matches) {
    p.push_back(query.at(m.query).position);
    q.push_back(map.at(m.map).position);
  }
  return SolvePose(
      p, q, params.pose,
      PairTolerances(query, map, matches, AllOf(matches.size()), params.match.similarity));
}

// Drops inlier pairs whose residual under the solved pose exceeds `gate_m` (times the pair's
// scale tolerance) and refines the pose on the rest (from the solved pose); keeps the estimate
// when fewer than min_inliers pairs would remain.
void GateResiduals(const IndexedLandmarks& query, const IndexedLandmarks& map,
                   const std::vector<Match>& matches, const RelocalizationParams& params,
                   PoseEstimate& estimate) {
  const double gate_m = params.final_residual_gate_m;
  if (gate_m <= 0.0) return;
  std::vector<Eigen::Vector3d> p(matches.size()), q(matches.size());
  for (size_t i = 0; i < matches.size(); ++i) {
    p[i] = query.at(matches[i].query).position;
    q[i] = map.at(matches[i].map).position;
  }
  const std::vector<double> tolerance =
      PairTolerances(query, map, matches, AllOf(matches.size()), params.match.similarity);
  std::vector<size_t> kept;
  for (size_t i : estimate.inliers) {
    if ((q[i] - estimate.map_from_query * p[i]).norm() / ToleranceOf(tolerance, i) <= gate_m)
      kept.push_back(i);
  }
  if (kept.size() == estimate.inliers.size() ||
      kept.size() < std::max<size_t>(params.pose.min_inliers, 3)) {
    return;
  }
  int iterations = 0;
  estimate.map_from_query = RefinePoseLevenbergMarquardt(p, q, kept, estimate.map_from_query,
                                                         params.pose, &iterations, tolerance);
  double squared = 0.0;
  for (size_t i : kept) {
    squared += (q[i] - estimate.map_from_query * p[i]).squaredNorm() /
               (ToleranceOf(tolerance, i) * ToleranceOf(tolerance, i));
  }
  estimate.rms_residual_m = std::sqrt(squared / static_cast<double>(kept.size()));
  estimate.inliers = std::move(kept);
}

}  // namespace

RelocalizationParams SeedMethodParams() {
  RelocalizationParams params;
  params.match.retrieval_labels = 1;
  params.final_residual_gate_m = 0.0;
  params.reliable_max_rms_m = 0.0;
  params.reliable_min_spread_m = 0.0;
  params.max_hypotheses = 1;
  params.twin.radius_m = 0.0;
  params.reliable_rotation_deg = 10.0;
  return params;
}

double SecondPrincipalSpread(const std::vector<Eigen::Vector3d>& positions) {
  if (positions.size() < 2) return 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& x : positions) mean += x;
  mean /= static_cast<double>(positions.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& x : positions) covariance += (x - mean) * (x - mean).transpose();
  covariance /= static_cast<double>(positions.size());
  // Eigenvalues ascending: index 1 is the second largest.
  const Eigen::Vector3d eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
          .eigenvalues();
  return std::sqrt(std::max(0.0, eigenvalues(1)));
}

namespace {

// Stage 2 (rematch_rounds re-match + solve rounds) from `start`; `initial` is the stage-1
// pose the reliability check compares against.
absl::StatusOr<RelocalizationResult> RematchAndSolve(const IndexedLandmarks& query,
                                                     const IndexedLandmarks& map,
                                                     const Eigen::Isometry3d& initial,
                                                     const Eigen::Isometry3d& start,
                                                     const RelocalizationParams& params) {
  RelocalizationResult result;
  result.initial_map_from_query = initial;
  result.map_from_query = start;
  for (int round = 0; round < std::max(1, params.rematch_rounds); ++round) {
    std::vector<Match> matches = MatchUnderPose(query, map, result.map_from_query, params.match);
    absl::StatusOr<PoseEstimate> solved = SolveFromMatches(query, map, matches, params);
    if (solved.ok()) GateResiduals(query, map, matches, params, *solved);
    if (!solved.ok()) {
      if (round > 0) break;  // keep the previous round's answer
      return absl::NotFoundError(
          absl::StrCat("re-match under the initial pose failed: ", solved.status().message()));
    }
    result.matches = std::move(matches);
    result.map_from_query = solved->map_from_query;
    result.inliers = std::move(solved->inliers);
    result.rms_residual_m = solved->rms_residual_m;
  }
  return result;
}

// Indices into result.matches of the inliers whose map landmark has no look-alike twin.
std::vector<size_t> DistinctiveInliers(const IndexedLandmarks& map,
                                       const RelocalizationResult& result, const TwinParams& twin) {
  std::vector<size_t> distinctive;
  for (size_t i : result.inliers) {
    if (!map.HasLookalikeWithin(result.matches[i].map, twin.radius_m, twin.min_cosine)) {
      distinctive.push_back(i);
    }
  }
  return distinctive;
}

// The pose solved (from the current one) from the distinctive inliers alone; nullopt when
// fewer than 3 of them or when every inlier is distinctive (nothing can be aliased).
std::optional<Eigen::Isometry3d> PoseFromDistinctiveInliers(const IndexedLandmarks& query,
                                                            const IndexedLandmarks& map,
                                                            const RelocalizationResult& result,
                                                            const std::vector<size_t>& distinctive,
                                                            const RelocalizationParams& params) {
  if (distinctive.size() < 3 || distinctive.size() == result.inliers.size()) return std::nullopt;
  std::vector<Eigen::Vector3d> p, q;
  for (size_t i : distinctive) {
    p.push_back(query.at(result.matches[i].query).position);
    q.push_back(map.at(result.matches[i].map).position);
  }
  int iterations = 0;
  return RefinePoseLevenbergMarquardt(
      p, q, AllOf(p.size()), result.map_from_query, params.pose, &iterations,
      PairTolerances(query, map, result.matches, distinctive, params.match.similarity));
}

void CheckReliability(const IndexedLandmarks& query, const IndexedLandmarks& map,
                      const RelocalizationParams& params, RelocalizationResult& result) {
  std::vector<Eigen::Vector3d> inlier_positions;
  for (size_t i : result.inliers) {
    inlier_positions.push_back(query.at(result.matches[i].query).position);
  }
  result.inlier_spread_m = SecondPrincipalSpread(inlier_positions);
  result.distinctive_inliers = result.inliers.size();
  result.distinctive_rms_m = result.rms_residual_m;
  if (params.twin.radius_m > 0.0) {
    const std::vector<size_t> distinctive = DistinctiveInliers(map, result, params.twin);
    const std::vector<double> tolerance =
        PairTolerances(query, map, result.matches, distinctive, params.match.similarity);
    double squared = 0.0;
    for (size_t k = 0; k < distinctive.size(); ++k) {
      const Match& m = result.matches[distinctive[k]];
      squared += (map.at(m.map).position - result.map_from_query * query.at(m.query).position)
                     .squaredNorm() /
                 (ToleranceOf(tolerance, k) * ToleranceOf(tolerance, k));
    }
    result.distinctive_inliers = distinctive.size();
    result.distinctive_rms_m =
        distinctive.empty() ? 0.0 : std::sqrt(squared / static_cast<double>(distinctive.size()));
  }
  // Twins agree with each other at a pitch offset and dilute the RMS of a bent pose; the
  // bound must also hold for the distinctive inliers once there are enough to judge (3).
  const bool distinctive_fit = params.reliable_max_rms_m <= 0.0 || result.distinctive_inliers < 3 ||
                               result.distinctive_rms_m <= params.reliable_max_rms_m;
  result.reliable =
      result.inliers.size() >= params.reliable_min_inliers &&
      (params.reliable_max_rms_m <= 0.0 || result.rms_residual_m <= params.reliable_max_rms_m) &&
      distinctive_fit && result.inlier_spread_m >= params.reliable_min_spread_m &&
      TranslationDifferenceM(result.map_from_query, result.initial_map_from_query) <=
          params.reliable_translation_m &&
      RotationDifferenceDeg(result.map_from_query, result.initial_map_from_query) <=
          params.reliable_rotation_deg;
}

// More inliers wins; equal counts: the lower RMS residual.
bool BetterSupported(const RelocalizationResult& a, const RelocalizationResult& b) {
  if (a.inliers.size() != b.inliers.size()) return a.inliers.size() > b.inliers.size();
  return a.rms_residual_m < b.rms_residual_m;
}

// Stage 2 from one initial pose, the alias check, then the reliability checks.
absl::StatusOr<RelocalizationResult> RefineHypothesis(const IndexedLandmarks& query,
                                                      const IndexedLandmarks& map,
                                                      const Eigen::Isometry3d& initial,
                                                      const RelocalizationParams& params) {
  absl::StatusOr<RelocalizationResult> result =
      RematchAndSolve(query, map, initial, initial, params);
  if (!result.ok()) return result;
  // Repeated structure (boxes on a shelf) can pull the pose one pitch off, bending it
  // through the few distinctive pairs. Re-solve from those alone and keep the better
  // supported of the two stage-2 answers.
  if (params.twin.radius_m > 0.0) {
    if (const std::optional<Eigen::Isometry3d> alternative = PoseFromDistinctiveInliers(
            query, map, *result, DistinctiveInliers(map, *result, params.twin), params);
        alternative && (TranslationDifferenceM(*alternative, result->map_from_query) >
                            params.twin.pose_tolerance_m ||
                        RotationDifferenceDeg(*alternative, result->map_from_query) >
                            params.twin.pose_tolerance_deg)) {
      absl::StatusOr<RelocalizationResult> other =
          RematchAndSolve(query, map, initial, *alternative, params);
      if (other.ok() && BetterSupported(*other, *result)) result = std::move(other);
    }
  }
  CheckReliability(query, map, params, *result);
  return result;
}

}  // namespace

absl::StatusOr<RelocalizationResult> Relocalize(const IndexedLandmarks& query,
                                                const IndexedLandmarks& map,
                                                const RelocalizationParams& params) {
  if (query.size() < 3) {
    return absl::NotFoundError(
        absl::StrCat("too few landmarks: ", query.size(), " observed, need at least 3"));
  }
  if (map.size() < 3) {
    return absl::NotFoundError(
        absl::StrCat("too few landmarks: the map has ", map.size(), ", need at least 3"));
  }
  NeighbourhoodMatcher matcher(query, map, params.match);
  size_t total_matches = 0;
  std::vector<Match> hypothesis_matches;  // stage-1 matches since the last hypothesis
  absl::Status last_error = absl::NotFoundError("not solved yet");
  std::optional<RelocalizationResult> best_unreliable;
  int hypotheses = 0;
  while (!matcher.exhausted() && hypotheses < std::max(1, params.max_hypotheses)) {
    const std::vector<Match> more = matcher.Next(params.match.early_stop_matches);
    total_matches += more.size();
    hypothesis_matches.insert(hypothesis_matches.end(), more.begin(), more.end());
    if (hypothesis_matches.size() < 3) continue;
    const absl::StatusOr<PoseEstimate> initial =
        SolveFromMatches(query, map, hypothesis_matches, params);
    if (!initial.ok()) {
      last_error = initial.status();
      continue;  // inconsistent: retrieve m more (seed 3.2)
    }
    ++hypotheses;
    hypothesis_matches.clear();  // the next hypothesis starts from fresh matches
    absl::StatusOr<RelocalizationResult> result =
        RefineHypothesis(query, map, initial->map_from_query, params);
    if (!result.ok()) {
      last_error = result.status();
      continue;
    }
    if (result->reliable) return result;
    if (!best_unreliable || result->inliers.size() > best_unreliable->inliers.size()) {
      best_unreliable = std::move(*result);
    }
  }
  if (best_unreliable) return *std::move(best_unreliable);
  if (total_matches < 3) {
    return absl::NotFoundError(absl::StrCat("no consistent match: only ", total_matches,
                                            " query landmarks found a match in the map"));
  }
  return last_error;
}

}  // namespace semnav::relocalization
