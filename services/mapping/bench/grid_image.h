#pragma once

#include <opencv2/core.hpp>

#include "services/mapping/core/grid_layers.h"

namespace semnav::mapping::bench {

// Side-by-side picture of the hierarchical layer (white free, black structure, red shades by
// obstacle height, grey unknown) and the obstacle probability map (darker = denser), y up.
cv::Mat RenderGridImage(const GridLayers& layers);

}  // namespace semnav::mapping::bench
