// Subjective-Bayes semantic value of every EROI (seed 000, 2.2.2, eq. 17-23). Values start at
// p~ = 1/N and never fall below it, so low-valued regions keep being explored.
#pragma once

#include <vector>

namespace semnav::reasoning {

class SemanticValues {
 public:
  explicit SemanticValues(int eroi_count);  // eq. 17: s(e) = 1/N

  // Eq. 18-20: a VLM code is strong positive evidence C(E|S) = 5 spread over the m EROIs of its
  // neighbourhood: s <- (1 - 1/m) s + 1/m.
  void ApplyVlmEvidence(const std::vector<int>& neighbourhood);
  // Eq. 21-23 for a region unit of k EROIs scored s(r) in [-5, 5] by the LLM:
  //   s(r) in [-5, 0]: s <- p~ + (s - p~) (s(r)/5 + 1) / k      (eq. 21 as printed)
  //   s(r) in (0, 5]:  s <- s + (1 - s) s(r) / (5 k)            (eq. 22)
  //   then s >= p~                                               (eq. 23)
  void ApplyRegionScore(const std::vector<int>& region, int score);

  double prior() const { return prior_; }
  double value(int eroi) const { return values_[static_cast<std::size_t>(eroi)]; }
  const std::vector<double>& values() const { return values_; }

 private:
  double prior_;
  std::vector<double> values_;
};

}  // namespace semnav::reasoning
