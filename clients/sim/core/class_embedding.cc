#include "clients/sim/core/class_embedding.h"

#include <cmath>

namespace semnav::sim {
namespace {

void Normalise(std::vector<float>& v) {
  double norm2 = 0.0;
  for (float x : v) norm2 += static_cast<double>(x) * x;
  const double inv = norm2 > 0.0 ? 1.0 / std::sqrt(norm2) : 0.0;
  for (float& x : v) x = static_cast<float>(x * inv);
}

}  // namespace

std::vector<float> ClassEmbedding(std::string_view label, int dim, uint64_t seed) {
  Rng rng(MixSeed(seed, HashString(label)));
  std::vector<float> v(dim);
  for (float& x : v) x = static_cast<float>(rng.Normal());
  Normalise(v);
  return v;
}

std::vector<float> NoisyEmbedding(const std::vector<float>& base, double noise, Rng& rng) {
  std::vector<float> v = base;
  const double per_component = noise / std::sqrt(static_cast<double>(base.size()));
  for (float& x : v) x = static_cast<float>(x + rng.Normal(0.0, per_component));
  Normalise(v);
  return v;
}

double CosineSimilarity(const std::vector<float>& a, const std::vector<float>& b) {
  double dot = 0.0, na = 0.0, nb = 0.0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
    dot += static_cast<double>(a[i]) * b[i];
    na += static_cast<double>(a[i]) * a[i];
    nb += static_cast<double>(b[i]) * b[i];
  }
  return na > 0.0 && nb > 0.0 ? dot / std::sqrt(na * nb) : 0.0;
}

}  // namespace semnav::sim
