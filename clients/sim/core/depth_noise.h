#pragma once

#include <cstdint>
#include <vector>

#include "clients/sim/core/view_renderer.h"

namespace semnav::sim {

// Axial depth noise growing with distance, sigma(z) = a + b (z - z0)^2 metres: the Kinect
// model of Nguyen, Izadi & Lovell (3DIMPVT 2012), sigma(1 m) = 1.9 mm, sigma(4 m) = 25.8 mm.
struct DepthNoiseModel {
  double a = 0.0012;
  double b = 0.0019;
  double z0 = 0.4;
  double Sigma(double z) const { return a + b * (z - z0) * (z - z0); }
};

// The view's depth with Gaussian noise per pixel, drawn from `seed`; noisy values outside
// [min_range, max_range] read as 0 (no return), as on a real sensor.
std::vector<float> NoisyDepth(const RenderedView& view, const DepthNoiseModel& model,
                              double min_range, double max_range, uint64_t seed);

}  // namespace semnav::sim
