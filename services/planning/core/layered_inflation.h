#pragma once

#include <optional>

#include "services/planning/core/layered_grid.h"

namespace semnav::planning {

// Footprint inflation of the hierarchical grid for a disc robot of radius_cells (cell units),
// so the multi-modal search can plan it as a point: every cell whose centre lies within the
// radius of a structure cell's centre becomes structure, and every other cell within the radius
// of an obstacle takes the tallest such obstacle's value (a robot rolling there would touch the
// obstacle, so it has to fly, above the tallest one it overlaps). Free cells farther away stay
// free. radius_cells <= 0 returns the grid unchanged.
LayeredGrid InflateLayeredGrid(const LayeredGrid& grid, double radius_cells);

// The cell nearest `start` (Euclidean, ties to the lower row then column) within radius_cells
// that is not structure in `grid`: where a robot whose start the inflation turned into structure
// (it stands near a wall) begins its search. nullopt when none lies that close.
std::optional<Cell> NearestPassableCell(const LayeredGrid& grid, Cell start, double radius_cells);

}  // namespace semnav::planning
