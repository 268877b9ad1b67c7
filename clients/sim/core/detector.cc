#include "clients/sim/core/detector.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "clients/sim/core/class_embedding.h"
#include "clients/sim/core/rng.h"

namespace semnav::sim {
namespace {

struct VisibleObject {
  std::vector<size_t> pixels;
  std::vector<float> depths;
  Eigen::Vector4i box{1 << 30, 1 << 30, -1, -1};
};

void AddPixel(VisibleObject& v, size_t i, int w, float depth) {
  const int u = static_cast<int>(i % w), row = static_cast<int>(i / w);
  v.pixels.push_back(i);
  v.depths.push_back(depth);
  v.box = Eigen::Vector4i(std::min(v.box[0], u), std::min(v.box[1], row), std::max(v.box[2], u),
                          std::max(v.box[3], row));
}

struct VisibleRegions {
  std::map<int, VisibleObject> things;         // per object index
  std::map<std::string, VisibleObject> stuff;  // per stuff kind: one segment per class
};

// Pixels per object and per stuff kind, in a fixed order so the random draws are reproducible.
VisibleRegions CollectVisible(const RenderedView& view, const Scene& scene,
                              const std::set<std::string>& stuff_kinds) {
  VisibleRegions visible;
  const int w = view.intrinsics.width;
  for (size_t i = 0; i < view.PixelCount(); ++i) {
    const int32_t s = view.surface[i];
    if (s < 0) continue;
    const SceneSolid& solid = scene.solids()[s];
    if (solid.object_index >= 0) {
      AddPixel(visible.things[solid.object_index], i, w, view.depth[i]);
    } else if (stuff_kinds.contains(solid.kind)) {
      AddPixel(visible.stuff[solid.kind], i, w, view.depth[i]);
    }
  }
  return visible;
}

std::vector<std::string> LabelPool(const World& world, const DetectorConfig& config) {
  std::set<std::string> labels(config.distractor_labels.begin(), config.distractor_labels.end());
  for (const ObjectInstance& o : world.objects) labels.insert(o.label);
  return {labels.begin(), labels.end()};
}

std::string OtherLabel(const std::vector<std::string>& pool, const std::string& label, Rng& rng) {
  std::vector<std::string> others;
  for (const std::string& l : pool) {
    if (l != label) others.push_back(l);
  }
  return others.empty() ? label : others[rng.UniformInt(0, static_cast<int>(others.size()) - 1)];
}

int Poisson(double mean, Rng& rng) {
  const double limit = std::exp(-mean);
  int k = 0;
  for (double p = rng.Uniform(); p > limit; p *= rng.Uniform()) ++k;
  return k;
}

Eigen::Vector4i JitterBox(const Eigen::Vector4i& box, double sigma, int w, int h, Rng& rng) {
  auto jitter = [&](int value, int hi) {
    return std::clamp(static_cast<int>(std::lround(value + rng.Normal(0.0, sigma))), 0, hi);
  };
  // The comma initialiser is sequenced left to right (C++17), so the draws keep their order.
  Eigen::Vector4i out;
  out << jitter(box[0], w - 1), jitter(box[1], h - 1), jitter(box[2], w - 1), jitter(box[3], h - 1);
  if (out[2] < out[0]) std::swap(out[0], out[2]);
  if (out[3] < out[1]) std::swap(out[1], out[3]);
  return out;
}

Eigen::Vector3d BackProject(const CameraIntrinsics& k, double u, double v, double depth) {
  return Eigen::Vector3d((u - k.cx) / k.fx * depth, (v - k.cy) / k.fy * depth, depth);
}

}  // namespace

DetectionFrame DetectObjects(const RenderedView& view, const Scene& scene, const World& world,
                             const DetectorConfig& config, uint64_t seed) {
  Rng rng(seed);
  DetectionFrame frame;
  frame.mask.assign(view.PixelCount(), 0);
  const std::vector<std::string> pool = LabelPool(world, config);
  const CameraIntrinsics& k = view.intrinsics;
  // Reports one visible region as `truth` (object -1 for stuff), after the miss and range tests.
  auto report = [&](VisibleObject& visible, const std::string& truth, int object) {
    if (static_cast<int>(visible.pixels.size()) < config.min_pixels) return;
    auto mid = visible.depths.begin() + visible.depths.size() / 2;
    std::nth_element(visible.depths.begin(), mid, visible.depths.end());
    const double median = *mid;
    if (median > config.max_range || rng.Bernoulli(config.miss_rate)) return;
    Detection d;
    const bool confused = rng.Bernoulli(config.confusion_rate);
    d.label = confused ? OtherLabel(pool, truth, rng) : truth;
    d.box = JitterBox(visible.box, config.box_noise_px, k.width, k.height, rng);
    d.depth_m = std::max(0.0, median + rng.Normal(0.0, config.depth_noise_m));
    // Confidence falls with distance; a confused label is reported less confidently.
    d.score = std::clamp(0.95 - 0.04 * median - (confused ? 0.2 : 0.0) + rng.Normal(0.0, 0.05),
                         0.05, 0.99);
    d.position_camera =
        BackProject(k, (d.box[0] + d.box[2]) / 2.0, (d.box[1] + d.box[3]) / 2.0, d.depth_m);
    d.embedding = NoisyEmbedding(ClassEmbedding(truth, config.embedding_dim, config.embedding_seed),
                                 config.embedding_noise, rng);
    d.pixel_count = static_cast<int>(visible.pixels.size());
    d.object_index = object;
    frame.detections.push_back(std::move(d));
    const auto tag = static_cast<uint16_t>(std::min<size_t>(frame.detections.size(), 65535));
    for (size_t i : visible.pixels) frame.mask[i] = tag;
  };
  const std::set<std::string> stuff_kinds(config.stuff_kinds.begin(), config.stuff_kinds.end());
  VisibleRegions visible = CollectVisible(view, scene, stuff_kinds);
  for (auto& [object, region] : visible.things) report(region, world.objects[object].label, object);
  for (auto& [kind, region] : visible.stuff) report(region, kind, -1);
  const int false_positives = Poisson(config.false_positive_rate, rng);
  for (int f = 0; f < false_positives; ++f) {
    // Boxes of 30-150 px on a 640 x 480 image, scaled with the image width.
    const double scale = k.width / 640.0;
    const int bw = rng.UniformInt(std::max(2, static_cast<int>(30 * scale)),
                                  std::max(2, static_cast<int>(150 * scale)));
    const int bh = rng.UniformInt(std::max(2, static_cast<int>(30 * scale)),
                                  std::max(2, static_cast<int>(150 * scale)));
    const int x0 = rng.UniformInt(0, k.width - bw - 1), y0 = rng.UniformInt(0, k.height - bh - 1);
    const size_t centre = static_cast<size_t>(y0 + bh / 2) * k.width + x0 + bw / 2;
    const double depth = view.depth[centre];
    if (depth <= 0.0) continue;  // a false positive still sits on some surface
    Detection d;
    d.label = pool[rng.UniformInt(0, static_cast<int>(pool.size()) - 1)];
    d.box = Eigen::Vector4i(x0, y0, x0 + bw, y0 + bh);
    d.depth_m = depth;
    d.score = rng.Uniform(0.25, 0.6);
    d.position_camera = BackProject(k, x0 + bw / 2.0, y0 + bh / 2.0, depth);
    d.embedding =
        NoisyEmbedding(ClassEmbedding(d.label, config.embedding_dim, config.embedding_seed),
                       config.embedding_noise, rng);
    frame.detections.push_back(std::move(d));
  }
  return frame;
}

}  // namespace semnav::sim
