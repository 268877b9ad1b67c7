#include "services/mapping/bench/grid_image.h"

namespace semnav::mapping::bench {

cv::Mat RenderGridImage(const GridLayers& layers) {
  const int w = layers.width;
  const int h = layers.height;
  cv::Mat image(h, 2 * w + 10, CV_8UC3, cv::Scalar(255, 255, 255));
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const size_t i = static_cast<size_t>(row) * w + col;
      const uint8_t v = layers.hierarchical[i];
      cv::Vec3b colour = v == HierarchicalGrid::kUnknown ? cv::Vec3b(160, 160, 160)
                         : v == HierarchicalGrid::kFree  ? cv::Vec3b(255, 255, 255)
                         : v == HierarchicalGrid::kStructure
                             ? cv::Vec3b(0, 0, 0)
                             : cv::Vec3b(40, 40, static_cast<uint8_t>(255 - v));
      image.at<cv::Vec3b>(h - 1 - row, col) = colour;
      const auto shade = static_cast<uint8_t>(255 - 255 * layers.obstacle_probability[i] / 100);
      image.at<cv::Vec3b>(h - 1 - row, w + 10 + col) =
          layers.explored[i] != 0 ? cv::Vec3b(shade, shade, shade) : cv::Vec3b(160, 160, 160);
    }
  }
  return image;
}

}  // namespace semnav::mapping::bench
