#include "services/reasoning/core/inverse_mapping.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace semnav::reasoning {

Eigen::Matrix3d BodyToOptical() {
  Eigen::Matrix3d r;
  r << 0, -1, 0,  //
      0, 0, -1,   //
      1, 0, 0;
  return r;
}

Eigen::Matrix3d WorldToOptical(const Eigen::Quaterniond& camera_orientation) {
  return BodyToOptical() * camera_orientation.normalized().toRotationMatrix().transpose();
}

InverseMapper::InverseMapper(const EroiGrid* grid, InverseMappingConfig config)
    : grid_(grid), config_(config) {}

std::vector<CodeLabel> InverseMapper::Project(const Eigen::Vector3d& camera_position,
                                              const Eigen::Quaterniond& camera_orientation,
                                              const PinholeCamera& camera) const {
  const Eigen::Matrix3d r_wc = WorldToOptical(camera_orientation);
  std::vector<CodeLabel> labels;
  for (int flat = 0; flat < grid_->size(); ++flat) {
    const Eigen::Vector3d world = grid_->Centre(flat);
    const Eigen::Vector3d p = r_wc * (world - camera_position);
    const double distance = p.norm();
    if (p.z() <= 0.0 || distance <= config_.min_distance_m || distance >= config_.max_distance_m)
      continue;
    const double u = camera.fx * p.x() / p.z() + camera.cx;
    const double v = camera.fy * p.y() / p.z() + camera.cy;
    if (u < 0.0 || v < 0.0 || u >= camera.width || v >= camera.height) continue;
    CodeLabel label;
    label.code = grid_->Encode(world);
    label.world = world;
    label.pixel = Eigen::Vector2d(u, v);
    label.distance_m = distance;
    int baseline = 0;
    const cv::Size text = cv::getTextSize(label.code, cv::FONT_HERSHEY_SIMPLEX, config_.font_scale,
                                          config_.font_thickness, &baseline);
    label.box = cv::Rect(static_cast<int>(u) - text.width / 2,
                         static_cast<int>(v) - text.height / 2, text.width, text.height + baseline);
    labels.push_back(std::move(label));
  }
  return labels;
}

std::vector<CodeLabel> InverseMapper::Cull(std::vector<CodeLabel> candidates) {
  std::stable_sort(
      candidates.begin(), candidates.end(),
      [](const CodeLabel& a, const CodeLabel& b) { return a.distance_m > b.distance_m; });
  std::vector<CodeLabel> accepted;
  for (CodeLabel& candidate : candidates) {
    const bool free = std::none_of(accepted.begin(), accepted.end(), [&](const CodeLabel& other) {
      return (candidate.box & other.box).area() > 0;
    });
    if (free) accepted.push_back(std::move(candidate));
  }
  return accepted;
}

void InverseMapper::Draw(const std::vector<CodeLabel>& labels, cv::Mat& image) const {
  for (const CodeLabel& label : labels) {
    cv::rectangle(image, label.box, cv::Scalar::all(0), cv::FILLED);
    int baseline = 0;
    const cv::Size text = cv::getTextSize(label.code, cv::FONT_HERSHEY_SIMPLEX, config_.font_scale,
                                          config_.font_thickness, &baseline);
    cv::putText(image, label.code, cv::Point(label.box.x, label.box.y + text.height),
                cv::FONT_HERSHEY_SIMPLEX, config_.font_scale, cv::Scalar::all(255),
                config_.font_thickness, cv::LINE_AA);
  }
}

}  // namespace semnav::reasoning
