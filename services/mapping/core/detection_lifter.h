#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "services/mapping/core/depth_projection.h"
#include "services/mapping/core/scene_types.h"
#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping {

struct LiftConfig {
  int erosion_kernel = 5;            // seed 004: 5x5 ones
  double erosion_keep_above = 23.5;  // seed 004
  int pixel_stride = 2;              // sampling of mask pixels for the 3D points
  // Points farther than this from the median depth are other surfaces seen through the mask.
  double depth_band_m = 0.3;
};

// A detection lifted to 3D (seed 002 "2D -> 3D projection").
struct LiftedDetection {
  ObjectObservation observation;
  std::vector<Eigen::Vector3f> points;  // labelled points in the map frame (for the semantic layer)
};

// Projects one detection: the mask (or the box when there is none) is eroded with the seed-004
// rule, its pixels with depth in range are back-projected; the robust depth is their median and
// only points within depth_band_m of it are kept (edges that jump to the background go). The
// object centre is the mean of the kept points, its size their 10-90 % extent per map axis.
// nullopt when no pixel survives.
std::optional<LiftedDetection> LiftDetection(const Detection& detection, const cv::Mat& depth_m,
                                             const Intrinsics& k, const CameraPose& pose,
                                             const DepthRange& range, const LiftConfig& config,
                                             int64_t stamp_ns, const std::string& robot_id);

}  // namespace semnav::mapping
