#include "services/mapping/core/detection_lifter.h"

#include <algorithm>
#include <cmath>

#include "services/mapping/core/semantic_filters.h"

namespace semnav::mapping {
namespace {

cv::Mat MaskOf(const Detection& detection, int width, int height) {
  if (!detection.mask.empty()) {
    return cv::Mat(height, width, CV_8U, const_cast<uint8_t*>(detection.mask.data())) != 0;
  }
  cv::Mat mask = cv::Mat::zeros(height, width, CV_8U);
  const PixelBox& b = detection.box;
  const cv::Rect box(
      cv::Point(static_cast<int>(std::floor(b.x_min)), static_cast<int>(std::floor(b.y_min))),
      cv::Point(static_cast<int>(std::ceil(b.x_max)), static_cast<int>(std::ceil(b.y_max))));
  mask(box & cv::Rect(0, 0, width, height)) = 255;
  return mask;
}

double Percentile(std::vector<double> values, double q) {
  const auto index = static_cast<size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(index),
                   values.end());
  return values[index];
}

}  // namespace

std::optional<LiftedDetection> LiftDetection(const Detection& detection, const cv::Mat& depth_m,
                                             const Intrinsics& k, const CameraPose& pose,
                                             const DepthRange& range, const LiftConfig& config,
                                             int64_t stamp_ns, const std::string& robot_id) {
  const cv::Mat mask = ErodeSemanticMask(MaskOf(detection, depth_m.cols, depth_m.rows) / 255,
                                         config.erosion_kernel, config.erosion_keep_above);
  std::vector<cv::Point> pixels;
  std::vector<double> depths;
  for (int v = 0; v < mask.rows; v += config.pixel_stride) {
    for (int u = 0; u < mask.cols; u += config.pixel_stride) {
      const float z = depth_m.at<float>(v, u);
      if (mask.at<uint8_t>(v, u) == 0 || !(z >= range.min_m && z <= range.max_m)) continue;
      pixels.emplace_back(u, v);
      depths.push_back(z);
    }
  }
  if (pixels.empty()) return std::nullopt;
  const double median = Percentile(depths, 0.5);
  const Eigen::Matrix3d rotation = pose.orientation.toRotationMatrix();
  LiftedDetection lifted;
  std::array<std::vector<double>, 3> coords;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < pixels.size(); ++i) {
    if (std::abs(depths[i] - median) > config.depth_band_m) continue;
    const Eigen::Vector3d p =
        rotation * BackProject(k, pixels[i].x, pixels[i].y, depths[i]) + pose.position;
    lifted.points.push_back(p.cast<float>());
    sum += p;
    for (int a = 0; a < 3; ++a) coords[a].push_back(p[a]);
  }
  ObjectObservation& o = lifted.observation;
  o.label = detection.label;
  o.score = detection.score;
  o.position = sum / static_cast<double>(lifted.points.size());
  for (int a = 0; a < 3; ++a) o.size[a] = Percentile(coords[a], 0.9) - Percentile(coords[a], 0.1);
  o.embedding = detection.embedding;
  o.stamp_ns = stamp_ns;
  o.robot_id = robot_id;
  return lifted;
}

}  // namespace semnav::mapping
