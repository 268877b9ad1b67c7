#include "services/relocalization/eval/scenario.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "services/common/geometry/kd_tree.h"
#include "services/relocalization/core/indexed_landmarks.h"

namespace semnav::relocalization::eval {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr size_t kShelfColumns = 8;
constexpr size_t kShelfLevels = 3;
constexpr double kShelfPitchM = 0.6;

using Rng = std::mt19937;

double Uniform(Rng& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Prototype of each label: 1 at the label's entry, U(0, 0.5) elsewhere.
std::vector<Descriptor> MakePrototypes(const ScenarioParams& p, Rng& rng) {
  std::vector<Descriptor> out(p.labels, Descriptor(p.descriptor_dim));
  for (size_t l = 0; l < p.labels; ++l) {
    for (size_t d = 0; d < p.descriptor_dim; ++d) {
      out[l][d] = d == l ? 1.0f : static_cast<float>(Uniform(rng, 0.0, 0.5));
    }
  }
  return out;
}

Descriptor Perturb(const Descriptor& base, double sigma, Rng& rng) {
  std::normal_distribution<double> n(0.0, sigma);
  Descriptor out = base;
  for (float& v : out) v = static_cast<float>(v + n(rng));
  return out;
}

// A keyframe pose (the query frame is the robot's keyframe frame) 2-6 m from `target`.
Eigen::Isometry3d RandomPoseNear(const Eigen::Vector3d& target, const ScenarioParams& p, Rng& rng) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(Uniform(rng, -180.0, 180.0) * kDeg, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(Uniform(rng, -p.max_tilt_deg, p.max_tilt_deg) * kDeg,
                                     Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(Uniform(rng, -p.max_tilt_deg, p.max_tilt_deg) * kDeg,
                                     Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  const double bearing = Uniform(rng, -std::numbers::pi, std::numbers::pi);
  const double range = Uniform(rng, 2.0, 6.0);
  pose.translation() = Eigen::Vector3d(target.x() + range * std::cos(bearing),
                                       target.y() + range * std::sin(bearing), 1.5);
  return pose;
}

void AddShelves(const ScenarioParams& p, const Descriptor& box, size_t count, Rng& rng,
                Scenario& s) {
  const double box_scale = Uniform(rng, p.scale_min_m, p.scale_max_m) * 0.5;
  while (count > 0) {
    const Eigen::Vector3d origin(Uniform(rng, 0.0, p.area_m), Uniform(rng, 0.0, p.area_m), 0.3);
    const Eigen::Vector3d along =
        Eigen::AngleAxisd(std::floor(Uniform(rng, 0.0, 4.0)) * 90.0 * kDeg,
                          Eigen::Vector3d::UnitZ()) *
        Eigen::Vector3d::UnitX();
    for (size_t c = 0; c < kShelfColumns && count > 0; ++c) {
      for (size_t level = 0; level < kShelfLevels && count > 0; ++level, --count) {
        Landmark l;
        l.position =
            origin + along * (c * kShelfPitchM) + Eigen::Vector3d::UnitZ() * (level * kShelfPitchM);
        l.scale = box_scale * Uniform(rng, 0.95, 1.05);
        l.descriptor = Perturb(box, 0.02, rng);
        s.map.push_back(std::move(l));
        s.lookalike.push_back(true);
      }
    }
  }
}

// The keyframe noise model applied to map landmarks `seen`, plus `extra` false landmarks
// spread over the bounding box of what is seen.
Keyframe Observe(const Scenario& s, const ScenarioParams& p, const std::vector<Descriptor>& protos,
                 const std::vector<size_t>& seen, const Eigen::Isometry3d& map_from_query,
                 size_t extra, Rng& rng) {
  Keyframe k;
  k.map_from_query = map_from_query;
  const Eigen::Isometry3d query_from_map = map_from_query.inverse();
  std::normal_distribution<double> pos(0.0, p.position_noise_m), rel(0.0, p.scale_noise);
  const double smoke_sigma = p.smoke / std::sqrt(static_cast<double>(p.descriptor_dim));
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e18), hi = -lo;
  for (size_t m : seen) {
    Landmark l;
    l.position = query_from_map * s.map[m].position + Eigen::Vector3d(pos(rng), pos(rng), pos(rng));
    l.scale = std::max(0.01, s.map[m].scale * (1.0 + rel(rng)));
    l.descriptor = Perturb(UnitDescriptor(s.map[m].descriptor), smoke_sigma, rng);
    lo = lo.cwiseMin(l.position);
    hi = hi.cwiseMax(l.position);
    k.observed.push_back(std::move(l));
    k.truth.push_back(static_cast<int64_t>(m));
  }
  for (size_t f = 0; f < extra; ++f) {
    Landmark l;
    for (int a = 0; a < 3; ++a) l.position[a] = Uniform(rng, lo[a] - 0.5, hi[a] + 0.5);
    l.scale = Uniform(rng, p.scale_min_m, p.scale_max_m);
    const size_t label = std::uniform_int_distribution<size_t>(0, p.labels - 1)(rng);
    l.descriptor =
        Perturb(UnitDescriptor(Perturb(protos[label], p.descriptor_spread, rng)), smoke_sigma, rng);
    k.observed.push_back(std::move(l));
    k.truth.push_back(-1);
  }
  // Shuffle so that order carries no information about truth.
  std::vector<size_t> order(k.observed.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  Keyframe shuffled;
  shuffled.map_from_query = k.map_from_query;
  for (size_t i : order) {
    shuffled.observed.push_back(k.observed[i]);
    shuffled.truth.push_back(k.truth[i]);
  }
  return shuffled;
}

// Prototypes are derived from the seed alone so that ObserveRegion reproduces them.
std::vector<Descriptor> PrototypesFor(const ScenarioParams& p) {
  Rng rng(p.seed);
  return MakePrototypes(p, rng);
}

}  // namespace

Scenario GenerateScenario(const ScenarioParams& p) {
  const std::vector<Descriptor> protos = PrototypesFor(p);
  Rng rng(p.seed * 7919u + 1u);
  Scenario s;
  const size_t boxes = static_cast<size_t>(p.lookalike_fraction * p.map_landmarks);
  const Descriptor box = Perturb(protos[0], p.descriptor_spread, rng);
  AddShelves(p, box, boxes, rng, s);
  while (s.map.size() < p.map_landmarks) {
    Landmark l;
    l.position = {Uniform(rng, 0.0, p.area_m), Uniform(rng, 0.0, p.area_m),
                  Uniform(rng, 0.0, p.height_m)};
    l.scale = Uniform(rng, p.scale_min_m, p.scale_max_m);
    const size_t label = std::uniform_int_distribution<size_t>(0, p.labels - 1)(rng);
    l.descriptor = Perturb(protos[label], p.descriptor_spread, rng);
    s.map.push_back(std::move(l));
    s.lookalike.push_back(false);
  }
  std::vector<Eigen::Vector3d> positions;
  for (const Landmark& l : s.map) positions.push_back(l.position);
  const geometry::KdTree<double> tree(positions);
  const size_t in_view = static_cast<size_t>(
      std::ceil(static_cast<double>(p.observed_true) / (1.0 - p.missing_fraction)));
  std::vector<size_t> shelf_boxes, others;
  for (size_t i = 0; i < s.map.size(); ++i) (s.lookalike[i] ? shelf_boxes : others).push_back(i);
  for (size_t k = 0; k < p.keyframes; ++k) {
    const bool on_shelf =
        !shelf_boxes.empty() && Uniform(rng, 0.0, 1.0) < p.view_on_lookalike_fraction;
    const std::vector<size_t>& pool = on_shelf || others.empty() ? shelf_boxes : others;
    const size_t centre = pool[std::uniform_int_distribution<size_t>(0, pool.size() - 1)(rng)];
    std::vector<size_t> view = tree.Nearest(s.map[centre].position, in_view);
    std::shuffle(view.begin(), view.end(), rng);
    view.resize(std::min(view.size(), p.observed_true));
    s.keyframes.push_back(Observe(
        s, p, protos, view, RandomPoseNear(s.map[centre].position, p, rng), p.observed_false, rng));
  }
  return s;
}

Keyframe ObserveRegion(const Scenario& scenario, const ScenarioParams& params,
                       const Eigen::Vector3d& centre, double radius_m,
                       const Eigen::Isometry3d& map_from_b, size_t extra, uint32_t seed) {
  Rng rng(seed);
  std::vector<size_t> seen;
  for (size_t i = 0; i < scenario.map.size(); ++i) {
    if ((scenario.map[i].position - centre).norm() <= radius_m &&
        Uniform(rng, 0.0, 1.0) >= params.missing_fraction) {
      seen.push_back(i);
    }
  }
  return Observe(scenario, params, PrototypesFor(params), seen, map_from_b, extra, rng);
}

}  // namespace semnav::relocalization::eval
