#include "services/relocalization/core/relocalizer.h"

#include <algorithm>

#include "absl/strings/str_cat.h"

namespace semnav::relocalization {
namespace {

absl::StatusOr<PoseEstimate> SolveFromMatches(const IndexedLandmarks& query,
                                              const IndexedLandmarks& map,
                                              const std::vector<Match>& matches,
                                              const PoseParams& params) {
  std::vector<Eigen::Vector3d> p, q;
  for (const Match& m : matches) {
    p.push_back(query.at(m.query).position);
    q.push_back(map.at(m.map).position);
  }
  return SolvePose(p, q, params);
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
  std::vector<Match> initial_matches;
  absl::StatusOr<PoseEstimate> initial = absl::NotFoundError("not solved yet");
  while (!matcher.exhausted()) {
    const std::vector<Match> more = matcher.Next(params.match.early_stop_matches);
    initial_matches.insert(initial_matches.end(), more.begin(), more.end());
    if (initial_matches.size() < 3) continue;
    initial = SolveFromMatches(query, map, initial_matches, params.pose);
    if (initial.ok()) break;
  }
  if (!initial.ok() && initial_matches.size() < 3) {
    return absl::NotFoundError(absl::StrCat("no consistent match: only ", initial_matches.size(),
                                            " query landmarks found a match in the map"));
  }
  if (!initial.ok()) return initial.status();

  RelocalizationResult result;
  result.initial_map_from_query = initial->map_from_query;
  result.map_from_query = initial->map_from_query;
  for (int round = 0; round < std::max(1, params.rematch_rounds); ++round) {
    std::vector<Match> matches = MatchUnderPose(query, map, result.map_from_query, params.match);
    absl::StatusOr<PoseEstimate> solved = SolveFromMatches(query, map, matches, params.pose);
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
  result.reliable =
      result.inliers.size() >= params.reliable_min_inliers &&
      TranslationDifferenceM(result.map_from_query, result.initial_map_from_query) <=
          params.reliable_translation_m &&
      RotationDifferenceDeg(result.map_from_query, result.initial_map_from_query) <=
          params.reliable_rotation_deg;
  return result;
}

}  // namespace semnav::relocalization
