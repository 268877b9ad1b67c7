#include "services/mapping/core/hierarchical_grid.h"

#include <algorithm>
#include <cmath>

namespace semnav::mapping {
namespace {

double Logit(double p) { return std::log(p / (1.0 - p)); }

// What one observation says about one grid cell (the strongest covering column wins).
struct CellObservation {
  bool structure = false;
  bool obstacle = false;
  double top_m = 0.0;
};

}  // namespace

uint8_t HierarchicalGrid::HeightValue(double z_m) const {
  const double h = 100.0 * (z_m - heights_.foot_m) / (heights_.ceiling_m - heights_.foot_m);
  return static_cast<uint8_t>(std::clamp(std::lround(h), 1L, 99L));
}

std::vector<int> HierarchicalGrid::CoveredCells(double c_m, double voxel_m) const {
  const double half_span = voxel_m / (config_.resolution_m * 2.0);  // R_o / (R_g * 2)
  const int base = static_cast<int>(std::floor(c_m / config_.resolution_m));
  std::vector<int> cells;
  // Small epsilon: R_o / (2 R_g) is an integer in exact arithmetic for the usual resolutions.
  for (int m = static_cast<int>(std::ceil(-half_span - 1e-9));
       m <= static_cast<int>(std::floor(half_span + 1e-9)); ++m) {
    cells.push_back(base + m);
  }
  return cells;
}

CellIndex HierarchicalGrid::CellOf(double x_m, double y_m) const {
  return {static_cast<int>(std::floor(x_m / config_.resolution_m)),
          static_cast<int>(std::floor(y_m / config_.resolution_m))};
}

void HierarchicalGrid::Update(const VoxelColumns& columns,
                              const absl::flat_hash_set<VoxelColumns::ColumnId>& observed,
                              std::vector<CellIndex>* turned_occupied) {
  absl::flat_hash_map<CellIndex, CellObservation> observation;
  const double voxel = columns.resolution();
  for (VoxelColumns::ColumnId id : observed) {
    const ColumnResult result = ClimbColumn(columns, id, heights_);
    if (result.kind == ColumnClass::kUnknown) continue;
    const std::vector<int> xs = CoveredCells(columns.KeyToCoord(VoxelColumns::XKey(id)), voxel);
    const std::vector<int> ys = CoveredCells(columns.KeyToCoord(VoxelColumns::YKey(id)), voxel);
    for (int x : xs) {
      for (int y : ys) {
        CellObservation& o = observation[CellIndex{x, y}];
        o.structure = o.structure || result.kind == ColumnClass::kStructure;
        if (result.kind == ColumnClass::kObstacle) {
          o.top_m = o.obstacle ? std::max(o.top_m, result.top_m) : result.top_m;
          o.obstacle = true;
        }
      }
    }
  }
  const auto hit = static_cast<float>(Logit(config_.p_hit));
  const auto miss = static_cast<float>(Logit(config_.p_miss));
  const auto occupied_log_odds = static_cast<float>(Logit(config_.p_threshold));
  const auto reads_occupied = [&](const Cell& cell) {
    return cell.structure || cell.log_odds >= occupied_log_odds;
  };
  for (const auto& [index, o] : observation) {
    const auto [it, is_new] = cells_.try_emplace(index);
    Cell& cell = it->second;
    const bool was_occupied = !is_new && reads_occupied(cell);
    cell.structure = o.structure;
    if (!o.structure) {
      cell.log_odds = std::clamp(cell.log_odds + (o.obstacle ? hit : miss),
                                 static_cast<float>(config_.log_odds_min),
                                 static_cast<float>(config_.log_odds_max));
      if (o.obstacle) cell.height = HeightValue(o.top_m);
    }
    if (turned_occupied != nullptr && !was_occupied && reads_occupied(cell)) {
      turned_occupied->push_back(index);
    }
  }
}

double HierarchicalGrid::Probability(CellIndex index) const {
  const auto it = cells_.find(index);
  if (it == cells_.end()) return 0.5;
  return 1.0 / (1.0 + std::exp(-static_cast<double>(it->second.log_odds)));
}

uint8_t HierarchicalGrid::Value(CellIndex index) const {
  const auto it = cells_.find(index);
  if (it == cells_.end()) return kUnknown;
  if (it->second.structure) return kStructure;
  return Probability(index) >= config_.p_threshold ? it->second.height : kFree;
}

std::vector<HierarchicalGrid::CellState> HierarchicalGrid::Cells() const {
  std::vector<CellState> out;
  out.reserve(cells_.size());
  for (const auto& [index, cell] : cells_)
    out.push_back({index, cell.log_odds, cell.height, cell.structure});
  std::sort(out.begin(), out.end(), [](const CellState& a, const CellState& b) {
    return a.index.x != b.index.x ? a.index.x < b.index.x : a.index.y < b.index.y;
  });
  return out;
}

void HierarchicalGrid::RestoreCells(const std::vector<CellState>& cells) {
  cells_.clear();
  cells_.reserve(cells.size());
  for (const CellState& c : cells) cells_[c.index] = Cell{c.log_odds, c.height, c.structure};
}

bool HierarchicalGrid::Bounds(CellIndex* min, CellIndex* max) const {
  if (cells_.empty()) return false;
  *min = *max = cells_.begin()->first;
  for (const auto& [index, cell] : cells_) {
    min->x = std::min(min->x, index.x);
    min->y = std::min(min->y, index.y);
    max->x = std::max(max->x, index.x);
    max->y = std::max(max->y, index.y);
  }
  return true;
}

}  // namespace semnav::mapping
