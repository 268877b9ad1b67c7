#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/world.h"

// Ground-truth 2D grids of a world, for the planner's shortest path l_i in SPL.
namespace semnav::sim {

struct GroundTruthGrid {
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  // world xy of cell (0, 0)'s corner
  double resolution = 0.05;                          // metres per cell
  int width = 0;                                     // cells along x
  int height = 0;                                    // cells along y
  std::vector<uint8_t> cells;                        // row-major, y rows
  uint8_t at(int x, int y) const { return cells[static_cast<size_t>(y) * width + x]; }
  Eigen::Vector2d CellCentre(int x, int y) const {
    return origin + resolution * Eigen::Vector2d(x + 0.5, y + 0.5);
  }
  // The cell holding world point `p`; nullopt off the grid.
  std::optional<Eigen::Vector2i> CellOf(const Eigen::Vector2d& p) const {
    const Eigen::Vector2d local = (p - origin) / resolution;
    const Eigen::Vector2i cell(static_cast<int>(std::floor(local.x())),
                               static_cast<int>(std::floor(local.y())));
    if (cell.x() < 0 || cell.y() < 0 || cell.x() >= width || cell.y() >= height)
      return std::nullopt;
    return cell;
  }
};

struct RasterOptions {
  double resolution = 0.05;
  double robot_radius = 0.25;  // occupied cells are dilated by this (configuration space)
  double z_min = 0.05;         // height band the robot body sweeps; solids outside it are
  double z_max = 1.5;          // passable (rugs below, overhangs above)
};

// The raster a robot's body meets at `altitude`: dilated by its radius, over the height band it
// sweeps there (a UAV passes over low obstacles; a fly-roll robot's is its rolling band).
RasterOptions BodyRaster(const RobotConfig& robot, double altitude);

// Occupancy: 100 where a solid overlapping [z_min, z_max] comes within half a cell of the cell
// centre, or within robot_radius of such a cell; else 0. Covers the world bounds.
GroundTruthGrid RasterizeOccupancy(const World& world, const RasterOptions& options);

// Seed 003's layered obstacle grid (section 2.1): 0 free, 100 structure (kinds "wall" and
// "building", and anything reaching `ceiling_m`), 1-99 the obstacle top height scaled by
// ceiling_m, for the fly-roll planner. Not inflated.
GroundTruthGrid RasterizeHeightLayers(const World& world, double resolution, double ceiling_m);

}  // namespace semnav::sim
