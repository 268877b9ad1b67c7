#include "services/mapping/core/scan_matcher.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "absl/container/flat_hash_set.h"
#include "absl/strings/str_cat.h"

namespace semnav::mapping {

Eigen::Vector2d PlanarCorrection::Apply(const Eigen::Vector2d& p) const {
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  return {c * p.x() - s * p.y() + x, s * p.x() + c * p.y() + y};
}

PlanarCorrection PlanarCorrection::After(const PlanarCorrection& other) const {
  const Eigen::Vector2d t = Apply({other.x, other.y});
  return {t.x(), t.y(), std::remainder(yaw + other.yaw, 2.0 * M_PI)};
}

namespace {

// exp(-d^2 / 2 sigma^2) per raster cell, d the distance to the nearest occupied cell.
cv::Mat LikelihoodField(const OccupiedRaster& map, double sigma_m) {
  cv::Mat free_mask(map.height, map.width, CV_8U);
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      free_mask.at<uint8_t>(row, col) =
          map.occupied[static_cast<size_t>(row) * map.width + col] != 0 ? 0 : 255;
    }
  }
  cv::Mat distance;
  cv::distanceTransform(free_mask, distance, cv::DIST_L2, cv::DIST_MASK_5);
  cv::Mat field(map.height, map.width, CV_32F);
  const double inv = 1.0 / (2.0 * sigma_m * sigma_m);
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      const double d = distance.at<float>(row, col) * map.resolution;
      field.at<float>(row, col) = static_cast<float>(std::exp(-d * d * inv));
    }
  }
  return field;
}

}  // namespace

absl::StatusOr<ScanMatchResult> MatchScan(const OccupiedRaster& map,
                                          const std::vector<Eigen::Vector2d>& scan,
                                          const PlanarCorrection& coarse,
                                          const ScanMatchConfig& config) {
  if (map.width <= 0 || map.height <= 0 || map.resolution <= 0.0 ||
      map.occupied.size() != static_cast<size_t>(map.width) * map.height) {
    return absl::InvalidArgumentError("the occupied raster's size does not match its cells");
  }
  const double res = map.resolution;
  // One point per cell of the reported frame: a wall seen in many frames counts once.
  absl::flat_hash_set<std::pair<int64_t, int64_t>> seen;
  std::vector<Eigen::Vector2d> cells;
  for (const Eigen::Vector2d& p : scan) {
    if (!p.allFinite()) continue;
    const std::pair<int64_t, int64_t> key{static_cast<int64_t>(std::floor(p.x() / res)),
                                          static_cast<int64_t>(std::floor(p.y() / res))};
    if (seen.insert(key).second) {
      cells.push_back(coarse.Apply({(key.first + 0.5) * res, (key.second + 0.5) * res}));
    }
  }
  ScanMatchResult result;
  result.correction = coarse;
  result.scan_cells = static_cast<int>(cells.size());
  if (result.scan_cells < config.min_scan_cells) {
    return absl::FailedPreconditionError(absl::StrCat(
        "the scan has ", result.scan_cells, " obstacle cells, need ", config.min_scan_cells));
  }
  if (std::none_of(map.occupied.begin(), map.occupied.end(), [](uint8_t v) { return v != 0; }))
    return result;  // nothing mapped to match against: the coarse pose stands

  const cv::Mat field = LikelihoodField(map, config.sigma_m);
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& c : cells) centroid += c;
  centroid /= static_cast<double>(cells.size());

  const int reach = static_cast<int>(std::lround(config.linear_window_m / res));
  const int turns =
      config.angular_step_rad > 0.0
          ? static_cast<int>(std::floor(config.angular_window_rad / config.angular_step_rad))
          : 0;
  const double n = static_cast<double>(cells.size());
  std::vector<int> cols(cells.size());
  std::vector<int> rows(cells.size());
  double best_score = -1.0;
  double best_cost = 0.0;
  PlanarCorrection best_local;
  // Yaws and offsets nearest the coarse pose first; a later candidate must score strictly higher
  // (or the same with a smaller change), so ties keep the smaller correction.
  for (int k = -turns; k <= turns; ++k) {
    const double dyaw = k * config.angular_step_rad;
    const double c = std::cos(dyaw);
    const double s = std::sin(dyaw);
    for (size_t i = 0; i < cells.size(); ++i) {
      const Eigen::Vector2d d = cells[i] - centroid;
      const double x = c * d.x() - s * d.y() + centroid.x();
      const double y = s * d.x() + c * d.y() + centroid.y();
      cols[i] = static_cast<int>(std::floor((x - map.origin_x) / res));
      rows[i] = static_cast<int>(std::floor((y - map.origin_y) / res));
    }
    for (int oy = -reach; oy <= reach; ++oy) {
      for (int ox = -reach; ox <= reach; ++ox) {
        double sum = 0.0;
        for (size_t i = 0; i < cells.size(); ++i) {
          const int col = cols[i] + ox;
          const int row = rows[i] + oy;
          if (col < 0 || row < 0 || col >= map.width || row >= map.height) continue;
          sum += field.at<float>(row, col);
        }
        const double score = sum / n;
        const double cost = std::hypot(ox * res, oy * res) + std::abs(dyaw);
        if (k == 0 && ox == 0 && oy == 0) result.coarse_score = score;
        if (score > best_score + 1e-12 ||
            (std::abs(score - best_score) <= 1e-12 && cost < best_cost)) {
          best_score = score;
          best_cost = cost;
          // Rotate about the centroid, then shift: p -> R (p - c) + c + o.
          const Eigen::Vector2d shift = centroid -
                                        Eigen::Vector2d(c * centroid.x() - s * centroid.y(),
                                                        s * centroid.x() + c * centroid.y()) +
                                        Eigen::Vector2d(ox * res, oy * res);
          best_local = {shift.x(), shift.y(), dyaw};
        }
      }
    }
  }
  result.score = best_score;
  if (best_score >= config.min_score && best_score >= result.coarse_score + config.min_gain) {
    result.correction = best_local.After(coarse);
    result.refined = true;
  }
  return result;
}

}  // namespace semnav::mapping
