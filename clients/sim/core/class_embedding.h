#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "clients/sim/core/rng.h"

namespace semnav::sim {

// A unit vector per class, fixed by (label, seed): the simulator's stand-in for a
// detector's appearance embedding. Different classes are nearly orthogonal.
std::vector<float> ClassEmbedding(std::string_view label, int dim, uint64_t seed);

// `base` plus isotropic Gaussian noise of total norm about `noise`, renormalised: the cosine
// similarity to the class vector is then about 1 / sqrt(1 + noise^2).
std::vector<float> NoisyEmbedding(const std::vector<float>& base, double noise, Rng& rng);

double CosineSimilarity(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace semnav::sim
