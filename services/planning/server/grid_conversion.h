#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "semnav/common/v1/geometry.pb.h"
#include "semnav/common/v1/grid.pb.h"
#include "services/planning/core/cell_grid.h"
#include "services/planning/core/jump_astar.h"

namespace semnav::planning {

// Placement of a GridMap in the map frame.
struct GridFrame {
  double resolution = 0.0;
  double origin_x = 0.0;
  double origin_y = 0.0;
  int width = 0;
  int height = 0;

  // The cell containing (x, y); INVALID_ARGUMENT naming `field` when outside.
  absl::StatusOr<Cell> ToCell(const semnav::common::v1::Pose2D& pose,
                              const std::string& field) const;
  // The cell containing (x, y), which may lie outside the grid (a planner may pad to it);
  // INVALID_ARGUMENT naming `field` when the pose is not finite or bounded.
  absl::StatusOr<Cell> ToCellAnywhere(const semnav::common::v1::Pose2D& pose,
                                      const std::string& field) const;
  // The centre of `cell`, yaw 0.
  semnav::common::v1::Pose2D ToPose(Cell cell) const;
};

// Checked GridMap geometry; INVALID_ARGUMENT naming the field (prefix
// `field`, e.g. "grid") when resolution, size or a layer's data is wrong.
absl::StatusOr<GridFrame> ReadGridFrame(const semnav::common::v1::GridMap& grid,
                                        const std::string& field);

// The bytes of the layer of `kind`, or nullptr when absent.
const std::string* FindLayer(const semnav::common::v1::GridMap& grid,
                             semnav::common::v1::GridLayerKind kind);

struct TraversabilityRules {
  int occupied_percent = 65;
  bool unknown_is_free = false;
};

// 2D traversability: from HIERARCHICAL (any non-zero blocks) or else
// OCCUPANCY (>= occupied_percent blocks); 255 = unknown per the rules.
// FAILED_PRECONDITION naming `field` when neither layer is present.
absl::StatusOr<PassabilityGrid> ToPassability(const semnav::common::v1::GridMap& grid,
                                              const TraversabilityRules& rules,
                                              const std::string& field);

// The seed 004 obstacle probability layer in percent (unknown = 0, as the
// seed treats unobserved cells as obstacle-free); empty grid when absent.
CellGrid<uint8_t> ToObstacleProbability(const semnav::common::v1::GridMap& grid);

// The EXPLORED layer (1 observed); FAILED_PRECONDITION naming `field` when
// absent.
absl::StatusOr<CellGrid<uint8_t>> ToExplored(const semnav::common::v1::GridMap& grid,
                                             const std::string& field);

// The seed 003 hierarchical layer for Jump A*; unknown (255) becomes
// structure unless unknown_is_free. FAILED_PRECONDITION when absent.
absl::StatusOr<LayeredGrid> ToLayeredGrid(const semnav::common::v1::GridMap& grid,
                                          bool unknown_is_free, const std::string& field);

// Marks each of `contacts` (map frame) as an obstacle in `grid`'s HIERARCHICAL and OCCUPANCY
// layers: every cell whose centre lies within radius_m of the point, and the cell under it.
// Building structure stays structure; an obstacle takes the tallest obstacle height within
// 0.5 m of the point (what the robot met is part of it), or the tallest flyable height when
// none is mapped there. Points outside the grid change nothing. The grid's geometry must have
// been checked (ReadGridFrame).
void StampContacts(const std::vector<Eigen::Vector2d>& contacts, double radius_m,
                   semnav::common::v1::GridMap& grid);

}  // namespace semnav::planning
