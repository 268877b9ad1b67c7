#pragma once

#include <cstdint>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "services/mapping/core/climbing.h"
#include "services/mapping/core/voxel_columns.h"

namespace semnav::mapping {

// Parameters of the hierarchical grid (seed 003 sec. 2.2-2.3).
struct HierarchicalGridConfig {
  double resolution_m = 0.05;  // R_g
  double p_hit = 0.7;          // p(G = occ | o_t) for a cell observed as obstacle (eq. 7)
  double p_miss = 0.4;         // p(G = occ | o_t) for a cell observed free (eq. 7)
  double p_threshold = 0.65;   // p_th of eq. 9
  // Log-odds clamp so a cell that was static for long can still clear (as in OctoMap).
  double log_odds_min = -2.0;
  double log_odds_max = 3.5;
};

struct CellIndex {
  int x = 0;
  int y = 0;
  bool operator==(const CellIndex&) const = default;
  template <typename H>
  friend H AbslHashValue(H h, const CellIndex& c) {
    return H::combine(std::move(h), c.x, c.y);
  }
};

// The building-structure layer (100) and the Bayesian obstacle-height layer (1-99) of seed 003.
class HierarchicalGrid {
 public:
  static constexpr uint8_t kFree = 0;
  static constexpr uint8_t kStructure = 100;
  static constexpr uint8_t kUnknown = 255;

  HierarchicalGrid(const HierarchicalGridConfig& config, const ClimbingHeights& heights)
      : config_(config), heights_(heights) {}

  // One observation o_t: the `observed` voxel columns are classified by climbing, each column
  // covers grid cells by eq. 1-2, a cell takes the highest obstacle voxel covering it (eq. 3-4),
  // and its log-odds moves by eq. 6-7 (obstacle: logit(p_hit), free: logit(p_miss)). Structure
  // cells are 100. With `turned_occupied`, the cells that read as free or unknown before and as
  // obstacle or structure after are appended to it.
  void Update(const VoxelColumns& columns,
              const absl::flat_hash_set<VoxelColumns::ColumnId>& observed,
              std::vector<CellIndex>* turned_occupied = nullptr);

  // Eq. 9: 100 structure; h_o when p_t >= p_th; 0 when observed and below; 255 never observed.
  uint8_t Value(CellIndex cell) const;
  // p_t of eq. 8 (0.5 for a cell never observed).
  double Probability(CellIndex cell) const;
  bool Explored(CellIndex cell) const { return cells_.contains(cell); }

  // Eq. 3: h_o = 100 (z - h_f) / (h_c - h_f), kept in 1-99 so it never reads as free or structure.
  uint8_t HeightValue(double z_m) const;
  // Eq. 1-2: the grid cell indices covered by a voxel centred at coordinate c (one axis).
  std::vector<int> CoveredCells(double c_m, double voxel_m) const;

  CellIndex CellOf(double x_m, double y_m) const;
  const HierarchicalGridConfig& config() const { return config_; }
  const ClimbingHeights& heights() const { return heights_; }
  // Bounding box of every explored cell (min, max inclusive); false if empty.
  bool Bounds(CellIndex* min, CellIndex* max) const;
  size_t CellCount() const { return cells_.size(); }

  // The accumulated state of one explored cell, for saving a map and loading it unchanged.
  struct CellState {
    CellIndex index;
    float log_odds = 0.0f;
    uint8_t height = 0;
    bool structure = false;
  };
  // Every explored cell, sorted by (x, y) so equal grids save to equal bytes.
  std::vector<CellState> Cells() const;
  // Replaces every cell by `cells` (a grid saved by Cells() at the same resolution).
  void RestoreCells(const std::vector<CellState>& cells);

 private:
  struct Cell {
    float log_odds = 0.0f;
    uint8_t height = 0;
    bool structure = false;
  };
  HierarchicalGridConfig config_;
  ClimbingHeights heights_;
  absl::flat_hash_map<CellIndex, Cell> cells_;
};

}  // namespace semnav::mapping
