#include "clients/sim/worlds/start_poses.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <numbers>
#include <utility>

#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/robot_config.h"

namespace semnav::sim {
GroundTruthGrid ModalityGrid(const World& world, Modality modality, double altitude) {
  RasterOptions options = BodyRaster(RobotConfig::ForModality(modality), altitude);
  options.resolution = 0.1;
  return RasterizeOccupancy(world, options);
}

namespace {

// Calls visit(index) for each 4-neighbour of cell (x, y) inside the grid, in the order +x, -x,
// +y, -y (the order breaks ties in the searches below).
template <typename Visit>
void ForEachNeighbour4(const GroundTruthGrid& grid, int x, int y, Visit visit) {
  const int nx[4] = {x + 1, x - 1, x, x}, ny[4] = {y, y, y + 1, y - 1};
  for (int k = 0; k < 4; ++k) {
    if (nx[k] < 0 || ny[k] < 0 || nx[k] >= grid.width || ny[k] >= grid.height) continue;
    visit(static_cast<size_t>(ny[k]) * grid.width + nx[k]);
  }
}

// The 4-connected components of the free cells (value 0), numbered in raster order of their
// first cell; each component's cells in breadth-first order from that cell.
struct FreeComponents {
  std::vector<int> label;                  // per cell: its component, -1 when not free
  std::vector<std::vector<size_t>> cells;  // per component
};

FreeComponents LabelFreeComponents(const GroundTruthGrid& grid) {
  FreeComponents components;
  components.label.assign(grid.cells.size(), -1);
  for (size_t seed = 0; seed < grid.cells.size(); ++seed) {
    if (grid.cells[seed] != 0 || components.label[seed] >= 0) continue;
    const int id = static_cast<int>(components.cells.size());
    std::vector<size_t> cells{seed};
    components.label[seed] = id;
    for (size_t i = 0; i < cells.size(); ++i) {
      const int x = static_cast<int>(cells[i] % grid.width);
      const int y = static_cast<int>(cells[i] / grid.width);
      ForEachNeighbour4(grid, x, y, [&](size_t n) {
        if (grid.cells[n] != 0 || components.label[n] >= 0) return;
        components.label[n] = id;
        cells.push_back(n);
      });
    }
    components.cells.push_back(std::move(cells));
  }
  return components;
}

// 1 for the free cells of components whose cells reach at least `min_radius_m` from the
// component's centroid (habitat-sim's island radius, on cell centres).
std::vector<uint8_t> CellsOnIslands(const GroundTruthGrid& grid, double min_radius_m) {
  std::vector<uint8_t> on(grid.cells.size(), 0);
  const auto centre = [&](size_t c) {
    return grid.CellCentre(static_cast<int>(c % grid.width), static_cast<int>(c / grid.width));
  };
  for (const std::vector<size_t>& island : LabelFreeComponents(grid).cells) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (const size_t c : island) sum += centre(c);
    const Eigen::Vector2d centroid = sum / static_cast<double>(island.size());
    double radius = 0.0;
    for (const size_t c : island) radius = std::max(radius, (centre(c) - centroid).norm());
    if (radius < min_radius_m) continue;
    for (const size_t c : island) on[c] = 1;
  }
  return on;
}

}  // namespace

std::vector<uint8_t> LargestFreeRegion(const GroundTruthGrid& grid) {
  const FreeComponents components = LabelFreeComponents(grid);
  std::vector<uint8_t> mask(grid.cells.size(), 0);
  if (components.cells.empty()) return mask;
  const auto largest =
      std::max_element(components.cells.begin(), components.cells.end(),
                       [](const std::vector<size_t>& a, const std::vector<size_t>& b) {
                         return a.size() < b.size();
                       });
  for (const size_t c : *largest) mask[c] = 1;
  return mask;
}

StartClearanceSearch::StartClearanceSearch(const World& world, Modality modality, double altitude,
                                           const StartClearance& clearance, PlaceFilter allowed)
    : grid_(ModalityGrid(world, modality, altitude)),
      region_(LargestFreeRegion(grid_)),
      scene_(Scene::Build(world)),
      allowed_(std::move(allowed)) {
  const RobotConfig robot = RobotConfig::ForModality(modality);
  RasterOptions band = BodyRaster(robot, altitude);
  radius_m_ = robot.radius + clearance.margin_m;
  z0_ = band.z_min;
  z1_ = band.z_max;
  band.resolution = grid_.resolution;
  band.robot_radius = radius_m_;
  clear_grid_ = RasterizeOccupancy(world, band);
  on_island_ = CellsOnIslands(clear_grid_, clearance.min_island_radius_m);
}

bool StartClearanceSearch::Clear(const Eigen::Vector2d& place) const {
  const std::optional<Eigen::Vector2i> cell = clear_grid_.CellOf(place);
  return cell.has_value() &&
         on_island_[static_cast<size_t>(cell->y()) * clear_grid_.width + cell->x()] != 0 &&
         !scene_.SolidTouchingCylinder(place, radius_m_, z0_, z1_).has_value();
}

std::optional<Eigen::Vector2d> StartClearanceSearch::Nearest(const Eigen::Vector2d& drawn) const {
  if (Clear(drawn)) return drawn;
  const std::optional<Eigen::Vector2i> from = grid_.CellOf(drawn);
  if (!from.has_value()) return std::nullopt;
  const auto index = [&](int x, int y) { return static_cast<size_t>(y) * grid_.width + x; };
  if (region_[index(from->x(), from->y())] == 0) return std::nullopt;
  // Breadth-first through the region: the first cell dequeued with clearance is the nearest by
  // steps; the neighbour order (+x, -x, +y, -y) breaks ties.
  std::vector<uint8_t> seen(region_.size(), 0);
  std::deque<Eigen::Vector2i> queue{*from};
  seen[index(from->x(), from->y())] = 1;
  while (!queue.empty()) {
    const Eigen::Vector2i c = queue.front();
    queue.pop_front();
    const Eigen::Vector2d centre = grid_.CellCentre(c.x(), c.y());
    if ((!allowed_ || allowed_(centre)) && Clear(centre)) return centre;
    ForEachNeighbour4(grid_, c.x(), c.y(), [&](size_t n) {
      if (region_[n] == 0 || seen[n] != 0) return;
      seen[n] = 1;
      queue.emplace_back(static_cast<int>(n % grid_.width), static_cast<int>(n / grid_.width));
    });
  }
  return std::nullopt;
}

std::vector<StartPose> ChooseStarts(const World& world, Modality modality, double altitude,
                                    int count, Rng& rng, const PlaceFilter& allowed,
                                    const StartClearance& clearance) {
  const StartClearanceSearch search(world, modality, altitude, clearance, allowed);
  const GroundTruthGrid& grid = search.grid();
  const std::vector<uint8_t>& region = search.region();
  // A start keeps one cell of margin inside the region: a cell centre is free of the dilated
  // solids, but the body there can still graze one (the raster is 0.1 m), and a robot that
  // starts in contact cannot move at all.
  const auto inside = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < grid.width && y < grid.height &&
           region[static_cast<size_t>(y) * grid.width + x] != 0;
  };
  std::vector<Eigen::Vector2d> cells;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      bool clear = true;
      for (int dy = -1; dy <= 1 && clear; ++dy) {
        for (int dx = -1; dx <= 1 && clear; ++dx) clear = inside(x + dx, y + dy);
      }
      if (clear && (!allowed || allowed(grid.CellCentre(x, y))))
        cells.push_back(grid.CellCentre(x, y));
    }
  }
  std::vector<StartPose> starts;
  if (cells.empty()) return starts;
  // The spread is checked between draws, not moved starts, so a move never changes a later draw.
  std::vector<Eigen::Vector2d> drawn;
  for (int k = 0; k < count; ++k) {
    Eigen::Vector2d pick = cells[rng.UniformInt(0, static_cast<int>(cells.size()) - 1)];
    for (int attempt = 0; attempt < 50; ++attempt) {
      bool spread = true;
      for (const Eigen::Vector2d& d : drawn) spread = spread && (d - pick).norm() >= 1.5;
      if (spread) break;
      pick = cells[rng.UniformInt(0, static_cast<int>(cells.size()) - 1)];
    }
    drawn.push_back(pick);
    const Eigen::Vector2d place = search.Nearest(pick).value_or(pick);
    StartPose start;
    start.position = Eigen::Vector3d(place.x(), place.y(), altitude);
    start.yaw = rng.Uniform(-std::numbers::pi, std::numbers::pi);
    start.modality = modality;
    starts.push_back(start);
  }
  return starts;
}

int RemoveUnreachableObjects(World& world, Modality modality, double altitude, double radius) {
  const GroundTruthGrid grid = ModalityGrid(world, modality, altitude);
  const std::vector<uint8_t> region = LargestFreeRegion(grid);
  const size_t before = world.objects.size();
  std::erase_if(world.objects, [&](const ObjectInstance& o) {
    const auto [lo, hi] = FootprintBounds(o.box);
    const int x0 =
        std::max(0, static_cast<int>((lo.x() - radius - grid.origin.x()) / grid.resolution));
    const int y0 =
        std::max(0, static_cast<int>((lo.y() - radius - grid.origin.y()) / grid.resolution));
    const int x1 = std::min(
        grid.width - 1, static_cast<int>((hi.x() + radius - grid.origin.x()) / grid.resolution));
    const int y1 = std::min(
        grid.height - 1, static_cast<int>((hi.y() + radius - grid.origin.y()) / grid.resolution));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        if (region[static_cast<size_t>(y) * grid.width + x] != 0 &&
            DistanceToBoxFootprint(o.box, grid.CellCentre(x, y)) <= radius) {
          return false;
        }
      }
    }
    return true;
  });
  return static_cast<int>(before - world.objects.size());
}

}  // namespace semnav::sim
