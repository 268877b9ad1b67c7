#pragma once

#include <cstdint>
#include <string_view>

namespace semnav::sim {

// 64-bit FNV-1a hash; stable across platforms, used to derive seeds from names.
uint64_t HashString(std::string_view text);

// Mixes several integers into one seed (splitmix64 finaliser).
uint64_t MixSeed(uint64_t a, uint64_t b);

// A small deterministic generator (splitmix64). Own Normal() instead of
// std::normal_distribution so the same seed gives the same numbers on any libstdc++.
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(seed) {}
  uint64_t Next();
  double Uniform();                      // [0, 1)
  double Uniform(double lo, double hi);  // [lo, hi)
  int UniformInt(int lo, int hi);        // [lo, hi] inclusive
  double Normal(double mean = 0.0, double stddev = 1.0);
  bool Bernoulli(double p) { return Uniform() < p; }

 private:
  uint64_t state_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace semnav::sim
