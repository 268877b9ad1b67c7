#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "services/relocalization/core/landmark.h"

namespace semnav::relocalization::eval {

// A seeded multi-session relocalization scenario (seed 001, 4.2): a prior landmark map,
// then keyframes that see subsets of it in their own odometry frame.
struct ScenarioParams {
  uint32_t seed = 1;
  // Prior map.
  size_t map_landmarks = 5000;
  double area_m = 100.0;  // landmarks lie in [0, area]^2 ...
  double height_m = 4.0;  // ... x [0, height]
  size_t labels = 16;     // label prototypes; descriptor arg-max = label
  size_t descriptor_dim = 32;
  double descriptor_spread = 0.15;  // per-object Gaussian spread around its prototype
  double scale_min_m = 0.2;         // object sizes, uniform
  double scale_max_m = 1.5;
  // Look-alikes (the seed's boxes on shelves): this fraction of the map are boxes of one
  // label and near-identical descriptor and size, on shelves of 8 x 3 at 0.6 m pitch.
  double lookalike_fraction = 0.2;
  // Keyframes.
  size_t keyframes = 200;
  size_t observed_true = 30;       // real landmarks seen per keyframe
  size_t observed_false = 20;      // extra false landmarks per keyframe (outliers)
  double missing_fraction = 0.2;   // landmarks in view that the keyframe misses
  double position_noise_m = 0.05;  // per-axis Gaussian sigma on observed positions
  double scale_noise = 0.1;        // relative Gaussian sigma on observed sizes
  // Descriptor degradation (the seed's smoke): observed unit descriptors get Gaussian
  // noise of expected norm `smoke` (per-entry sigma smoke / sqrt(descriptor_dim)).
  double smoke = 0.3;
  double view_on_lookalike_fraction = 0.0;  // keyframes centred on a shelf
  double max_tilt_deg = 5.0;                // roll / pitch of the keyframe frame; yaw is uniform
};

struct Keyframe {
  std::vector<Landmark> observed;  // in the keyframe's frame (robot 2-6 m away)
  std::vector<int64_t> truth;      // map index per observed landmark, -1 = false
  Eigen::Isometry3d map_from_query = Eigen::Isometry3d::Identity();  // ground truth
};

struct Scenario {
  std::vector<Landmark> map;
  std::vector<bool> lookalike;  // per map landmark
  std::vector<Keyframe> keyframes;
};

Scenario GenerateScenario(const ScenarioParams& params);

// Robot B's map for two-robot alignment: the map landmarks within `radius_m` of
// `centre`, seen in B's frame (map_from_b) with the keyframe noise model, plus
// `extra` false landmarks. Returned in B's frame with truth indices.
Keyframe ObserveRegion(const Scenario& scenario, const ScenarioParams& params,
                       const Eigen::Vector3d& centre, double radius_m,
                       const Eigen::Isometry3d& map_from_b, size_t extra, uint32_t seed);

}  // namespace semnav::relocalization::eval
