// Text grids for planning without a mapping service: one character per cell, in the Moving AI
// .map format or plain rows, converted to the values of a HIERARCHICAL grid layer.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"

namespace semnav::cli {

// Cells row-major; row r is the r-th map line (row 0 at the grid origin's y, as in Moving AI
// where y is the line index).
struct TextGrid {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> cells;
};

// Characters: '.', 'G', 'S' free (0); '1'-'9' a flyable obstacle of that height (in the map's
// height steps); '@', 'O', 'T', 'W', '#' structure (100); '?' unknown (255). An optional Moving AI
// header ("type ...", "height H", "width W", "map") is skipped and its size checked.
absl::StatusOr<TextGrid> ParseTextGrid(std::string_view text);

}  // namespace semnav::cli
