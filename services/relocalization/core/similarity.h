#pragma once

namespace semnav::relocalization {

// Weights and per-term thresholds of the object similarity (seed 001, 3.1):
// s = alpha s_pos + beta s_scale + gamma s_desc, or 0 when any term <= its threshold.
struct SimilarityParams {
  double alpha = 0.4;            // weight of the position term
  double beta = 0.2;             // weight of the scale term
  double gamma = 0.4;            // weight of the descriptor term
  double pos_threshold = 0.3;    // T_pos
  double scale_threshold = 0.5;  // T_scale
  double desc_threshold = 0.5;   // T_desc
  double pos_sigma_m = 0.2;      // s_pos = exp(-e^2 / (2 sigma^2)) for a position error e
  // Position tolerance that grows with the object (metres of centre uncertainty per metre of
  // scale): a pair's sigma is sqrt(pos_sigma_m^2 + (k max(scale))^2). The centre of what a camera
  // saw of a bed or a couch lies up to half its size from the box centre (measured 0.7-1.1 m on
  // 2 m objects, mission.md "Losing the pose"); seed 001's object points carry a scale for this.
  // Every metric test of matching and pose solving then uses the error divided by
  // ScaleTolerance. 0 = the seed's fixed sigma (the seed benchmark's 5 cm noise is size-free).
  double pos_sigma_per_scale = 0.0;
};

// The three similarity terms, each in [0, 1].
struct SimilarityTerms {
  double pos = 0.0;
  double scale = 0.0;
  double desc = 0.0;
};

// Gaussian of a position error in metres.
double PositionSimilarity(double error_m, double sigma_m);
// Ratio of the smaller to the larger size (0 if either is not positive).
double ScaleSimilarity(double scale_a, double scale_b);
// How much larger than pos_sigma_m a pair's position uncertainty is (>= 1; exactly 1 when
// pos_sigma_per_scale is 0): sqrt(pos_sigma_m^2 + (k max(scale_a, scale_b))^2) / pos_sigma_m.
double ScaleTolerance(const SimilarityParams& params, double scale_a, double scale_b);
// The gated weighted sum of seed 001, 3.1.
double CombinedSimilarity(const SimilarityTerms& terms, const SimilarityParams& params);

}  // namespace semnav::relocalization
