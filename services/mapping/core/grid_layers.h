#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "services/mapping/core/hierarchical_grid.h"

namespace semnav::mapping {

// A rectangle of grid cells: columns [min.x, min.x + width), rows [min.y, min.y + height).
struct GridWindow {
  CellIndex min;
  int width = 0;
  int height = 0;
};

struct GridLayersConfig {
  // Side of the ones kernel of the obstacle probability map (seed 004: 9).
  int obstacle_kernel = 9;
  // Robot radius for the inflated layer, metres.
  double robot_radius_m = 0.25;
};

// Row-major byte layers of one window (encodings as in semnav.common.v1.GridLayerKind).
struct GridLayers {
  double resolution = 0.0;
  double origin_x = 0.0;  // outer corner of cell (row 0, column 0), metres
  double origin_y = 0.0;
  int width = 0;
  int height = 0;
  ClimbingHeights heights;
  std::vector<uint8_t> hierarchical;          // 0 free, 1-99 height, 100 structure, 255 unknown
  std::vector<uint8_t> occupancy;             // Bayesian p_t in percent, 255 unknown
  std::vector<uint8_t> obstacle_probability;  // 9x9 ones convolution of the obstacle map, percent
  std::vector<uint8_t> explored;              // 1 observed, 0 not
  std::vector<uint8_t> inflated;  // 100 within robot radius of an obstacle, 0 free, 255 unknown
  std::vector<uint8_t> semantic;  // label index (semantic_labels[index - 1]), 0 none
  std::vector<std::string> semantic_labels;
};

// The window covering every explored cell (empty if none).
GridWindow FullWindow(const HierarchicalGrid& grid);

// Renders the geometric layers. Obstacle probability (seed 004): the binary obstacle map (any
// cell 1-100; unobserved counts as no obstacle, as in the seed) convolved with a k x k ones kernel
// and divided by k^2. The semantic layer is left empty (see SemanticMap::Render).
GridLayers RenderLayers(const HierarchicalGrid& grid, const GridWindow& window,
                        const GridLayersConfig& config);

}  // namespace semnav::mapping
