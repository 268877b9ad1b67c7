#pragma once

#include <opencv2/core.hpp>

#include "clients/sim/core/scene.h"
#include "clients/sim/core/view_renderer.h"

namespace semnav::sim {

// Flat-shaded colour image (CV_8UC3, BGR as OpenCV expects): each pixel is its surface colour
// times the Lambert factor; sky where nothing is hit. Object outlines are drawn dark so a
// vision model can separate touching objects of similar colour.
cv::Mat RenderRgb(const RenderedView& view, const Scene& scene);

}  // namespace semnav::sim
