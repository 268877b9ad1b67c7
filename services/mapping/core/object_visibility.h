#pragma once

#include <opencv2/core.hpp>

#include "services/mapping/core/scene_graph.h"
#include "services/mapping/core/scene_types.h"
#include "services/mapping/core/sensor_frame.h"

namespace semnav::mapping {

// Pixels of the image rectangle (width x height) that holds the projection of the object's box
// corners in front of the camera.
double ApparentArea(const SceneObject& object, const Intrinsics& k, const CameraPose& pose,
                    double width, double height);

// Whether a detector looking through this camera should have reported `object`: its centre lies
// in front of the camera within config.max_range_m, well inside the image (config.image_margin),
// its box's apparent area (ApparentArea) covers at least config.min_view_fraction of it, and the
// depth image at the centre's pixel reaches the object's front (less config.occlusion_tolerance_m):
// nothing nearer hides it. A pixel without a depth reading gives no evidence (false).
bool ExpectedInView(const SceneObject& object, const cv::Mat& depth_m, const Intrinsics& k,
                    const CameraPose& pose, const ExistenceConfig& config);

}  // namespace semnav::mapping
