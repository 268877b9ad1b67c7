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

PlanarCorrection PlanarCorrection::Inverse() const {
  const Eigen::Vector2d t = PlanarCorrection{0.0, 0.0, -yaw}.Apply({x, y});  // R^T (x, y)
  return {-t.x(), -t.y(), -yaw};
}

OccupiedRaster GridRaster(const HierarchicalGrid& grid, const GridWindow& window,
                          bool free_and_opaque) {
  OccupiedRaster raster;
  raster.resolution = grid.config().resolution_m;
  raster.origin_x = window.min.x * raster.resolution;
  raster.origin_y = window.min.y * raster.resolution;
  raster.width = window.width;
  raster.height = window.height;
  const size_t cells = static_cast<size_t>(raster.width) * raster.height;
  raster.occupied.assign(cells, 0);
  if (free_and_opaque) {
    raster.observed_free.assign(cells, 0);
    raster.opaque.assign(cells, 0);
  }
  for (int row = 0; row < raster.height; ++row) {
    for (int col = 0; col < raster.width; ++col) {
      const uint8_t value = grid.Value({window.min.x + col, window.min.y + row});
      const size_t i = static_cast<size_t>(row) * raster.width + col;
      raster.occupied[i] = value != HierarchicalGrid::kFree && value != HierarchicalGrid::kUnknown;
      if (free_and_opaque) {
        raster.observed_free[i] = value == HierarchicalGrid::kFree;
        raster.opaque[i] = value == HierarchicalGrid::kStructure;
      }
    }
  }
  return raster;
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

absl::Status CheckRaster(const OccupiedRaster& map) {
  const size_t cells = static_cast<size_t>(std::max(map.width, 0)) * std::max(map.height, 0);
  if (map.width <= 0 || map.height <= 0 || map.resolution <= 0.0 || map.occupied.size() != cells ||
      (!map.observed_free.empty() && map.observed_free.size() != cells) ||
      (!map.opaque.empty() && map.opaque.size() != cells)) {
    return absl::InvalidArgumentError("the occupied raster's size does not match its cells");
  }
  return absl::OkStatus();
}

// One point per cell of the reported frame (its centre): a wall seen in many frames counts once.
std::vector<Eigen::Vector2d> DistinctCells(const std::vector<Eigen::Vector2d>& scan, double res) {
  absl::flat_hash_set<std::pair<int64_t, int64_t>> seen;
  std::vector<Eigen::Vector2d> cells;
  for (const Eigen::Vector2d& p : scan) {
    if (!p.allFinite()) continue;
    const std::pair<int64_t, int64_t> key{static_cast<int64_t>(std::floor(p.x() / res)),
                                          static_cast<int64_t>(std::floor(p.y() / res))};
    if (seen.insert(key).second)
      cells.emplace_back((key.first + 0.5) * res, (key.second + 0.5) * res);
  }
  return cells;
}

absl::Status TooFewCells(size_t cells, int needed) {
  return absl::FailedPreconditionError(
      absl::StrCat("the scan has ", cells, " obstacle cells, need ", needed));
}

bool HasOccupied(const OccupiedRaster& map) {
  return std::any_of(map.occupied.begin(), map.occupied.end(), [](uint8_t v) { return v != 0; });
}

// Mean of `field` at the cells (cols[i] + col, rows[i] + row); cells outside count 0.
double MeanAt(const cv::Mat& field, const std::vector<int>& cols, const std::vector<int>& rows,
              int col, int row) {
  double sum = 0.0;
  const float* data = field.ptr<float>(0);
  const size_t stride = field.step1();
  for (size_t i = 0; i < cols.size(); ++i) {
    const int c = col + cols[i];
    const int r = row + rows[i];
    if (c < 0 || r < 0 || c >= field.cols || r >= field.rows) continue;
    sum += data[static_cast<size_t>(r) * stride + c];
  }
  return cols.empty() ? 0.0 : sum / static_cast<double>(cols.size());
}

}  // namespace

absl::StatusOr<ScanMatchResult> MatchScan(const OccupiedRaster& map,
                                          const std::vector<Eigen::Vector2d>& scan,
                                          const PlanarCorrection& coarse,
                                          const ScanMatchConfig& config) {
  if (absl::Status s = CheckRaster(map); !s.ok()) return s;
  const double res = map.resolution;
  std::vector<Eigen::Vector2d> cells = DistinctCells(scan, res);
  for (Eigen::Vector2d& c : cells) c = coarse.Apply(c);
  ScanMatchResult result;
  result.correction = coarse;
  result.scan_cells = static_cast<int>(cells.size());
  if (result.scan_cells < config.min_scan_cells)
    return TooFewCells(cells.size(), config.min_scan_cells);
  if (!HasOccupied(map)) return result;  // nothing mapped to match against: the coarse pose stands

  const cv::Mat field = LikelihoodField(map, config.sigma_m);
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& c : cells) centroid += c;
  centroid /= static_cast<double>(cells.size());

  const int reach = static_cast<int>(std::lround(config.linear_window_m / res));
  const int turns =
      config.angular_step_rad > 0.0
          ? static_cast<int>(std::floor(config.angular_window_rad / config.angular_step_rad))
          : 0;
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
        const double score = MeanAt(field, cols, rows, ox, oy);
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

namespace {

// A robot pose of the global search: the robot's cell in the raster and its heading.
struct GlobalPose {
  double score = 0.0;
  int col = 0;
  int row = 0;
  double yaw = 0.0;
};

// max of `field` over [row, row + k) x [col, col + k) (clamped at the far edges).
cv::Mat PooledField(const cv::Mat& field, int k) {
  cv::Mat along_rows(field.rows, field.cols, CV_32F);
  for (int row = 0; row < field.rows; ++row) {
    for (int col = 0; col < field.cols; ++col) {
      float best = 0.0f;
      for (int j = 0; j < k && col + j < field.cols; ++j)
        best = std::max(best, field.at<float>(row, col + j));
      along_rows.at<float>(row, col) = best;
    }
  }
  cv::Mat pooled(field.rows, field.cols, CV_32F);
  for (int row = 0; row < field.rows; ++row) {
    for (int col = 0; col < field.cols; ++col) {
      float best = 0.0f;
      for (int i = 0; i < k && row + i < field.rows; ++i)
        best = std::max(best, along_rows.at<float>(row + i, col));
      pooled.at<float>(row, col) = best;
    }
  }
  return pooled;
}

// Whole-cell offsets of the scan's cells from the robot's cell at heading `yaw`.
void Offsets(const std::vector<Eigen::Vector2d>& relative, double yaw, double res,
             std::vector<int>* cols, std::vector<int>* rows) {
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  cols->resize(relative.size());
  rows->resize(relative.size());
  for (size_t i = 0; i < relative.size(); ++i) {
    const Eigen::Vector2d& d = relative[i];
    (*cols)[i] = static_cast<int>(std::floor((c * d.x() - s * d.y()) / res + 0.5));
    (*rows)[i] = static_cast<int>(std::floor((s * d.x() + c * d.y()) / res + 0.5));
  }
}

// Share of the rays from the robot's cell to its scan cells (offsets at the pose) that pass
// through an opaque map cell and come out of it: `emerge` non-opaque cells in a row after it,
// all short of the ray's last `slack` cells (a grid line walk, Bresenham). A ray that only
// grazes the wall its end lies on never comes out of it. emerge <= 0: every wall met counts.
double RayConflicts(const OccupiedRaster& map, const std::vector<int>& cols,
                    const std::vector<int>& rows, int col, int row, int slack, int emerge) {
  if (cols.empty()) return 0.0;
  const std::vector<uint8_t>& opaque = map.opaque.empty() ? map.occupied : map.opaque;
  int conflicts = 0;
  for (size_t i = 0; i < cols.size(); ++i) {
    const int dx = cols[i];
    const int dy = rows[i];
    const int steps = std::max(std::abs(dx), std::abs(dy));
    bool in_wall = false;
    int beyond = 0;  // non-opaque cells in a row since the ray met a wall
    for (int t = 1; t < steps - slack; ++t) {
      const int c = col + static_cast<int>(std::lround(static_cast<double>(dx) * t / steps));
      const int r = row + static_cast<int>(std::lround(static_cast<double>(dy) * t / steps));
      if (c < 0 || r < 0 || c >= map.width || r >= map.height) break;
      if (opaque[static_cast<size_t>(r) * map.width + c] != 0) {
        in_wall = true;
        beyond = 0;
      } else if (in_wall) {
        ++beyond;
      }
      if (in_wall && beyond >= std::max(emerge, 0)) {
        ++conflicts;
        break;
      }
    }
  }
  return static_cast<double>(conflicts) / static_cast<double>(cols.size());
}

}  // namespace

absl::StatusOr<ScanMatchResult> MatchScanGlobally(const OccupiedRaster& map,
                                                  const std::vector<Eigen::Vector2d>& scan,
                                                  const Eigen::Vector2d& robot,
                                                  const ScanMatchConfig& local,
                                                  const GlobalMatchConfig& config) {
  if (absl::Status s = CheckRaster(map); !s.ok()) return s;
  const double res = map.resolution;
  const std::vector<Eigen::Vector2d> cells = DistinctCells(scan, res);
  ScanMatchResult result;
  result.scan_cells = static_cast<int>(cells.size());
  if (result.scan_cells < local.min_scan_cells)
    return TooFewCells(cells.size(), local.min_scan_cells);
  if (!HasOccupied(map)) return result;

  std::vector<Eigen::Vector2d> relative;
  relative.reserve(cells.size());
  for (const Eigen::Vector2d& c : cells) relative.push_back(c - robot);
  std::vector<Eigen::Vector2d> subset;
  const size_t wanted = static_cast<size_t>(std::max(1, config.max_coarse_scan_cells));
  const size_t stride = std::max<size_t>(1, (relative.size() + wanted - 1) / wanted);
  for (size_t i = 0; i < relative.size(); i += stride) subset.push_back(relative[i]);

  const cv::Mat field = LikelihoodField(map, local.sigma_m);
  const int k = std::max(1, config.coarse_cells);
  const cv::Mat pooled = PooledField(field, k);
  auto cell_centre = [&](int col, int row) {
    return Eigen::Vector2d(map.origin_x + (col + 0.5) * res, map.origin_y + (row + 0.5) * res);
  };
  auto self_match = [&](const Eigen::Vector2d& at, double yaw) {
    return (at - robot).norm() < config.self_match_m &&
           std::abs(std::remainder(yaw, 2.0 * M_PI)) < config.self_match_rad;
  };
  // Lattice cells whose block holds an observed-free cell.
  std::vector<std::pair<int, int>> lattice;
  for (int row = 0; row < map.height; row += k) {
    for (int col = 0; col < map.width; col += k) {
      bool free = map.observed_free.empty();
      for (int i = 0; i < k && !free && row + i < map.height; ++i) {
        for (int j = 0; j < k && !free && col + j < map.width; ++j)
          free = map.observed_free[static_cast<size_t>(row + i) * map.width + col + j] != 0;
      }
      if (free) lattice.emplace_back(col, row);
    }
  }
  // Coarse pass: the best few hundred (lattice cell, heading) by the pooled upper bound.
  constexpr size_t kKept = 512;
  auto better = [](const GlobalPose& a, const GlobalPose& b) { return a.score > b.score; };
  std::vector<GlobalPose> kept;  // a min-heap on score (front = the worst kept)
  const int headings =
      std::max(1, static_cast<int>(std::lround(2.0 * M_PI / config.angular_step_rad)));
  std::vector<int> cols;
  std::vector<int> rows;
  for (int h = 0; h < headings; ++h) {
    const double yaw = std::remainder(-M_PI + 2.0 * M_PI * h / headings, 2.0 * M_PI);
    Offsets(subset, yaw, res, &cols, &rows);
    for (const auto& [col, row] : lattice) {
      const double score = MeanAt(pooled, cols, rows, col, row);
      if (kept.size() == kKept && score <= kept.front().score) continue;
      if (self_match(cell_centre(col + k / 2, row + k / 2), yaw)) continue;
      kept.push_back({score, col, row, yaw});
      std::push_heap(kept.begin(), kept.end(), better);
      if (kept.size() > kKept) {
        std::pop_heap(kept.begin(), kept.end(), better);
        kept.pop_back();
      }
    }
  }
  std::sort(kept.begin(), kept.end(), better);  // best first
  // Refine the best mutually distinct candidates (half the distinctness of the answer check, so
  // a candidate near a higher bound still gets its own refinement).
  std::vector<GlobalPose> refined;
  std::vector<GlobalPose> chosen;
  const int turns =
      std::max(0, static_cast<int>(std::ceil(config.angular_step_rad / local.angular_step_rad)));
  for (const GlobalPose& candidate : kept) {
    if (static_cast<int>(chosen.size()) >= config.refine_candidates) break;
    const Eigen::Vector2d at = cell_centre(candidate.col, candidate.row);
    bool near_chosen = false;
    for (const GlobalPose& c : chosen) {
      near_chosen |=
          (at - cell_centre(c.col, c.row)).norm() < config.distinct_m / 2 &&
          std::abs(std::remainder(candidate.yaw - c.yaw, 2.0 * M_PI)) < config.distinct_rad / 2;
    }
    if (near_chosen) continue;
    chosen.push_back(candidate);
    GlobalPose best{-1.0, candidate.col, candidate.row, candidate.yaw};
    for (int t = -turns; t <= turns; ++t) {
      const double yaw = candidate.yaw + t * local.angular_step_rad;
      Offsets(relative, yaw, res, &cols, &rows);
      for (int row = candidate.row - 1; row <= candidate.row + k; ++row) {
        for (int col = candidate.col - 1; col <= candidate.col + k; ++col) {
          if (self_match(cell_centre(col, row), yaw)) continue;
          const double score = MeanAt(field, cols, rows, col, row);
          if (score > best.score + 1e-12) best = {score, col, row, yaw};
        }
      }
    }
    refined.push_back(best);
  }
  if (refined.empty()) return result;
  const GlobalPose top =
      *std::max_element(refined.begin(), refined.end(),
                        [](const GlobalPose& a, const GlobalPose& b) { return a.score < b.score; });
  const Eigen::Vector2d at = cell_centre(top.col, top.row);
  for (const GlobalPose& other : refined) {
    const bool distinct =
        (cell_centre(other.col, other.row) - at).norm() > config.distinct_m ||
        std::abs(std::remainder(other.yaw - top.yaw, 2.0 * M_PI)) > config.distinct_rad;
    if (distinct) result.runner_up_score = std::max(result.runner_up_score, other.score);
  }
  // The reported pose competes too (self_match): its best score within the window.
  const int col = static_cast<int>(std::floor((robot.x() - map.origin_x) / res));
  const int row = static_cast<int>(std::floor((robot.y() - map.origin_y) / res));
  for (int t = -turns; t <= turns; ++t) {
    const double yaw = t * local.angular_step_rad;
    Offsets(relative, yaw, res, &cols, &rows);
    for (int r = row - 2; r <= row + 2; ++r) {
      for (int c = col - 2; c <= col + 2; ++c) {
        result.runner_up_score = std::max(result.runner_up_score, MeanAt(field, cols, rows, c, r));
      }
    }
  }
  // The robot stands at `at`, turned by top.yaw from its reported heading: p -> R (p - robot) + at.
  const PlanarCorrection turn{0.0, 0.0, top.yaw};
  const Eigen::Vector2d shift = at - turn.Apply(robot);
  result.correction = {shift.x(), shift.y(), std::remainder(top.yaw, 2.0 * M_PI)};
  result.score = top.score;
  Offsets(relative, top.yaw, res, &cols, &rows);
  result.ray_conflicts = RayConflicts(map, cols, rows, top.col, top.row, config.ray_end_slack_cells,
                                      config.ray_emerge_cells);
  result.refined = top.score >= config.min_score &&
                   1.0 - result.runner_up_score >= config.min_misfit_ratio * (1.0 - top.score) &&
                   result.ray_conflicts <= config.max_ray_conflicts;
  return result;
}

}  // namespace semnav::mapping
