#include "services/mapping/core/semantic_map.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

#include "services/mapping/core/semantic_filters.h"

namespace semnav::mapping {

namespace {

std::array<int, 3> CubeOf(const Eigen::Vector3f& p, float edge) {
  return {static_cast<int>(std::floor(p.x() / edge)), static_cast<int>(std::floor(p.y() / edge)),
          static_cast<int>(std::floor(p.z() / edge))};
}

}  // namespace

void SemanticMap::Add(const std::string& label, const std::vector<Eigen::Vector3f>& points) {
  Add(label, points, [](const std::string&, const Eigen::Vector3f&) { return true; });
}

void SemanticMap::Add(const std::string& label, const std::vector<Eigen::Vector3f>& points,
                      SupportFn supported) {
  auto& cubes = occupied_cubes_[label];
  auto& per_voxel = points_per_voxel_[label];
  auto& kept = points_[label];
  const auto r = static_cast<float>(config_.point_resolution_m);
  for (const Eigen::Vector3f& p : points) {
    int& in_voxel = per_voxel[CubeOf(p, static_cast<float>(config_.cap_voxel_m))];
    if (in_voxel >= config_.max_points_per_voxel) continue;
    if (cubes.insert(CubeOf(p, r)).second) {
      kept.push_back(p);
      ++in_voxel;
    }
  }
  const double prune_at =
      std::max(static_cast<double>(config_.prune_min_points),
               config_.prune_growth * static_cast<double>(last_prune_[label].passing));
  if (static_cast<double>(kept.size()) >= prune_at) Prune(label, supported);
}

void SemanticMap::Prune(const std::string& label, SupportFn supported) {
  std::vector<Eigen::Vector3f>& points = points_[label];
  PruneState& last = last_prune_[label];
  const std::vector<bool> passes = RadiusFilter(points, config_.radius_m, config_.min_neighbours);
  std::vector<Eigen::Vector3f> kept;
  kept.reserve(points.size());
  size_t passing = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if ((passes[i] || i >= last.kept) && supported(label, points[i])) {
      kept.push_back(points[i]);
      if (passes[i]) ++passing;
    }
  }
  if (kept.empty()) {
    Forget(label);
    return;
  }
  points = std::move(kept);
  Reindex(label);
  last.kept = points.size();
  last.passing = passing;
}

void SemanticMap::Forget(const std::string& label) {
  points_.erase(label);
  occupied_cubes_.erase(label);
  points_per_voxel_.erase(label);
  last_prune_.erase(label);
}

void SemanticMap::Reindex(const std::string& label) {
  auto& cubes = occupied_cubes_[label];
  auto& per_voxel = points_per_voxel_[label];
  cubes.clear();
  per_voxel.clear();
  const auto r = static_cast<float>(config_.point_resolution_m);
  for (const Eigen::Vector3f& p : points_[label]) {
    cubes.insert(CubeOf(p, r));
    ++per_voxel[CubeOf(p, static_cast<float>(config_.cap_voxel_m))];
  }
}

size_t SemanticMap::KeepSupported(const std::set<std::string>& labels, SupportFn supported) {
  size_t dropped_total = 0;
  for (const std::string& label : labels) {
    const auto it = points_.find(label);
    if (it == points_.end()) continue;
    std::vector<Eigen::Vector3f>& points = it->second;
    PruneState& last = last_prune_[label];
    std::vector<Eigen::Vector3f> kept;
    kept.reserve(points.size());
    size_t dropped_before_last_prune = 0;
    for (size_t i = 0; i < points.size(); ++i) {
      if (supported(label, points[i])) {
        kept.push_back(points[i]);
      } else if (i < last.kept) {
        ++dropped_before_last_prune;
      }
    }
    const size_t dropped = points.size() - kept.size();
    if (dropped == 0) continue;
    dropped_total += dropped;
    if (kept.empty()) {
      Forget(label);
      continue;
    }
    points = std::move(kept);
    Reindex(label);
    // The older points stay at the front; those that passed at the last prune are now at most
    // the ones left of them.
    last.kept -= dropped_before_last_prune;
    last.passing = std::min(last.passing, last.kept);
  }
  return dropped_total;
}

void SemanticMap::Clear() {
  points_.clear();
  occupied_cubes_.clear();
  points_per_voxel_.clear();
  last_prune_.clear();
}

void SemanticMap::Render(GridLayers& layers) const {
  layers.semantic.assign(static_cast<size_t>(layers.width) * layers.height, 0);
  layers.semantic_labels.clear();
  for (const auto& [label, points] : points_) {
    layers.semantic_labels.push_back(label);
    const auto index = static_cast<uint8_t>(std::min<size_t>(layers.semantic_labels.size(), 255));
    const std::vector<bool> keep = RadiusFilter(points, config_.radius_m, config_.min_neighbours);
    cv::Mat cells = cv::Mat::zeros(layers.height, layers.width, CV_8U);
    for (size_t i = 0; i < points.size(); ++i) {
      if (!keep[i]) continue;
      const int col =
          static_cast<int>(std::floor((points[i].x() - layers.origin_x) / layers.resolution));
      const int row =
          static_cast<int>(std::floor((points[i].y() - layers.origin_y) / layers.resolution));
      if (col >= 0 && row >= 0 && col < layers.width && row < layers.height)
        cells.at<uint8_t>(row, col) = 1;
    }
    const cv::Mat opened = OpenSemanticLayer(cells, config_.opening_kernel);
    for (int row = 0; row < layers.height; ++row) {
      for (int col = 0; col < layers.width; ++col) {
        if (opened.at<uint8_t>(row, col) != 0)
          layers.semantic[static_cast<size_t>(row) * layers.width + col] = index;
      }
    }
  }
}

}  // namespace semnav::mapping
