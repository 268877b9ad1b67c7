// Spatial-visual inverse mapping (seed 000, 2.1.2): project EROI centres into the forward camera
// image and draw their codes, so the VLM can name a 3-D place by reading a label.
//   eq. 5-6  R_w^c = R_u^c (R_u^w)^T with R_u^c the fixed body->optical rotation
//   eq. 7    p^c = R_w^c (p^w - t^w), kept if Z > 0 and d_min < |p^c| < d_max
//   eq. 9    u = f_x X / Z + c_x, v = f_y Y / Z + c_y, kept inside the image
//   eq. 10   labels sorted by distance (descending, as the seed writes) and accepted only if their
//            box overlaps no accepted box.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "services/reasoning/core/eroi_grid.h"

namespace semnav::reasoning {

struct PinholeCamera {
  double fx = 0, fy = 0, cx = 0, cy = 0;  // pixels
  int width = 0, height = 0;              // pixels
};

struct InverseMappingConfig {
  double min_distance_m = 3.0;   // d_min (seed: 3-12 m in front of the UAV)
  double max_distance_m = 12.0;  // d_max
  double font_scale = 0.5;       // OpenCV Hershey simplex scale of the drawn codes
  int font_thickness = 1;
};

struct CodeLabel {
  std::string code;                                 // Algorithm 1 code of the EROI centre
  Eigen::Vector3d world = Eigen::Vector3d::Zero();  // EROI centre, world frame
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();  // (u, v)
  double distance_m = 0;                            // |p^c|
  cv::Rect box;                                     // text box centred on the pixel
};

// Eq. 5: camera body frame u (x forward, y left, z up) -> optical frame c (z forward, x right, y
// down).
Eigen::Matrix3d BodyToOptical();
// Eq. 6 for a camera orientation q = R_u^w.
Eigen::Matrix3d WorldToOptical(const Eigen::Quaterniond& camera_orientation);

class InverseMapper {
 public:
  InverseMapper(const EroiGrid* grid, InverseMappingConfig config);

  // Eq. 7 and 9 over all EROI centres: the visible candidates E_T with their label boxes.
  std::vector<CodeLabel> Project(const Eigen::Vector3d& camera_position,
                                 const Eigen::Quaterniond& camera_orientation,
                                 const PinholeCamera& camera) const;
  // Eq. 10 occlusion culling.
  static std::vector<CodeLabel> Cull(std::vector<CodeLabel> candidates);
  // Draws the labels (white text on a dark box) into `image` (8-bit, 1 or 3 channels).
  void Draw(const std::vector<CodeLabel>& labels, cv::Mat& image) const;

 private:
  const EroiGrid* grid_;
  InverseMappingConfig config_;
};

}  // namespace semnav::reasoning
