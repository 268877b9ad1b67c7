#include "clients/sim/core/depth_noise.h"

#include "clients/sim/core/rng.h"

namespace semnav::sim {

std::vector<float> NoisyDepth(const RenderedView& view, const DepthNoiseModel& model,
                              double min_range, double max_range, uint64_t seed) {
  Rng rng(seed);
  std::vector<float> depth(view.depth.size(), 0.0f);
  for (size_t i = 0; i < depth.size(); ++i) {
    const double z = view.depth[i];
    if (z <= 0.0) continue;
    const double noisy = z + rng.Normal(0.0, model.Sigma(z));
    if (noisy >= min_range && noisy <= max_range) depth[i] = static_cast<float>(noisy);
  }
  return depth;
}

}  // namespace semnav::sim
