#include "services/mapping/core/grid_layers.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace semnav::mapping {

GridWindow FullWindow(const HierarchicalGrid& grid) {
  CellIndex min;
  CellIndex max;
  if (!grid.Bounds(&min, &max)) return {};
  return {min, max.x - min.x + 1, max.y - min.y + 1};
}

GridLayers RenderLayers(const HierarchicalGrid& grid, const GridWindow& window,
                        const GridLayersConfig& config) {
  GridLayers layers;
  layers.resolution = grid.config().resolution_m;
  layers.origin_x = window.min.x * layers.resolution;
  layers.origin_y = window.min.y * layers.resolution;
  layers.width = window.width;
  layers.height = window.height;
  layers.heights = grid.heights();
  const size_t cells = static_cast<size_t>(window.width) * window.height;
  layers.hierarchical.resize(cells);
  layers.occupancy.resize(cells);
  layers.explored.resize(cells);
  layers.semantic.assign(cells, 0);
  if (cells == 0) return layers;

  cv::Mat obstacle(window.height, window.width, CV_8U, cv::Scalar(0));
  for (int row = 0; row < window.height; ++row) {
    for (int col = 0; col < window.width; ++col) {
      const CellIndex index{window.min.x + col, window.min.y + row};
      const size_t i = static_cast<size_t>(row) * window.width + col;
      const uint8_t value = grid.Value(index);
      const bool explored = grid.Explored(index);
      layers.hierarchical[i] = value;
      layers.explored[i] = explored ? 1 : 0;
      layers.occupancy[i] = explored
                                ? static_cast<uint8_t>(std::lround(100.0 * grid.Probability(index)))
                                : HierarchicalGrid::kUnknown;
      obstacle.at<uint8_t>(row, col) =
          (value >= 1 && value <= HierarchicalGrid::kStructure) ? 1 : 0;
    }
  }

  cv::Mat density;
  const int k = config.obstacle_kernel;
  cv::boxFilter(obstacle, density, CV_32F, cv::Size(k, k), cv::Point(-1, -1), /*normalize=*/true,
                cv::BORDER_CONSTANT);
  const int radius_cells = static_cast<int>(std::ceil(config.robot_radius_m / layers.resolution));
  cv::Mat inflated;
  cv::dilate(obstacle, inflated,
             cv::getStructuringElement(cv::MORPH_ELLIPSE,
                                       cv::Size(2 * radius_cells + 1, 2 * radius_cells + 1)),
             cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  layers.obstacle_probability.resize(cells);
  layers.inflated.resize(cells);
  for (int row = 0; row < window.height; ++row) {
    for (int col = 0; col < window.width; ++col) {
      const size_t i = static_cast<size_t>(row) * window.width + col;
      layers.obstacle_probability[i] =
          static_cast<uint8_t>(std::lround(100.0f * density.at<float>(row, col)));
      layers.inflated[i] = inflated.at<uint8_t>(row, col) != 0 ? 100
                           : layers.explored[i] != 0           ? 0
                                                               : HierarchicalGrid::kUnknown;
    }
  }
  return layers;
}

}  // namespace semnav::mapping
