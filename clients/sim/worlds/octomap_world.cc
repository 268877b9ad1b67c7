#include "clients/sim/worlds/octomap_world.h"

#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/worlds/scene_parts.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

const Rgb kWallColour{205, 200, 190};  // the scan's walls and the closed outside alike

struct VoxelGrid {
  Eigen::Vector3d origin;
  double resolution = 0.1;
  Eigen::Vector3i dims;
  std::vector<uint8_t> occupied;
  size_t Index(int x, int y, int z) const {
    return (static_cast<size_t>(z) * dims.y() + y) * dims.x() + x;
  }
  bool At(int x, int y, int z) const { return occupied[Index(x, y, z)] != 0; }
};

VoxelGrid Rasterize(const octomap::OcTree& tree) {
  VoxelGrid grid;
  grid.resolution = tree.getResolution();
  double x0, y0, z0, x1, y1, z1;
  tree.getMetricMin(x0, y0, z0);
  tree.getMetricMax(x1, y1, z1);
  grid.origin = Eigen::Vector3d(x0, y0, z0);
  grid.dims = Eigen::Vector3i(static_cast<int>(std::ceil((x1 - x0) / grid.resolution)),
                              static_cast<int>(std::ceil((y1 - y0) / grid.resolution)),
                              static_cast<int>(std::ceil((z1 - z0) / grid.resolution)));
  grid.occupied.assign(static_cast<size_t>(grid.dims.prod()), 0);
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (!tree.isNodeOccupied(*it)) continue;
    // Coarser leaves cover several finest voxels.
    const int n = static_cast<int>(std::lround(it.getSize() / grid.resolution));
    const Eigen::Vector3d corner = Eigen::Vector3d(it.getX(), it.getY(), it.getZ()) -
                                   Eigen::Vector3d::Constant(it.getSize() / 2) - grid.origin;
    const Eigen::Vector3i base = (corner / grid.resolution).array().round().cast<int>();
    for (int dz = 0; dz < n; ++dz)
      for (int dy = 0; dy < n; ++dy)
        for (int dx = 0; dx < n; ++dx) {
          const Eigen::Vector3i v = base + Eigen::Vector3i(dx, dy, dz);
          if ((v.array() >= 0).all() && (v.array() < grid.dims.array()).all()) {
            grid.occupied[grid.Index(v.x(), v.y(), v.z())] = 1;
          }
        }
  }
  return grid;
}

// The most occupied layer among those below 0.5 m: the floor.
int FloorLayer(const VoxelGrid& grid) {
  int best = -1;
  size_t best_count = 0;
  for (int z = 0; z < grid.dims.z() && grid.origin.z() + z * grid.resolution < 0.5; ++z) {
    size_t count = 0;
    for (int y = 0; y < grid.dims.y(); ++y)
      for (int x = 0; x < grid.dims.x(); ++x) count += grid.At(x, y, z) ? 1 : 0;
    if (count > best_count) {
      best_count = count;
      best = z;
    }
  }
  return best;
}

// Columns whose floor voxel the scan saw, widened by `widen` voxels to bridge holes: the
// building's inside. The rest of the map's bounds was never scanned (empty in the OctoMap, not
// known free): starts and objects there put the robot outside the building.
PlaceFilter SeenFloor(const VoxelGrid& grid, int floor, int widen) {
  const int w = grid.dims.x(), h = grid.dims.y();
  auto seen = std::make_shared<std::vector<uint8_t>>(static_cast<size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!grid.At(x, y, floor)) continue;
      for (int dy = -widen; dy <= widen; ++dy)
        for (int dx = -widen; dx <= widen; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < w && v < h) (*seen)[static_cast<size_t>(v) * w + u] = 1;
        }
    }
  const Eigen::Vector2d origin = grid.origin.head<2>();
  const double r = grid.resolution;
  return [seen, origin, r, w, h](const Eigen::Vector2d& p) {
    const int x = static_cast<int>(std::floor((p.x() - origin.x()) / r));
    const int y = static_cast<int>(std::floor((p.y() - origin.y()) / r));
    return x >= 0 && y >= 0 && x < w && y < h && (*seen)[static_cast<size_t>(y) * w + x] != 0;
  };
}

// Columns outside the scanned building. FR-079's scan shows its rooms' doors to the corridor
// closed and its outer walls with gaps (windows, open doors), and with the outside free a robot
// in a room drove out of the building and round it to the other rooms: every start and object
// was drawn in that region, the corridor was out of reach (docs/simulation.md, "FR-079").
// Habitat-Sim confines agents to the navmesh of the scanned floor for the same reason.
// Outside = never seen as floor, no structure, and reached from the edge of the bounds without
// passing within `gap_cells` of structure (gaps in the outer wall up to twice that stay closed;
// rooms whose floor the scan saw little of stay open), grown back by `gap_cells` toward the
// walls. The scanned floor is never outside.
std::vector<uint8_t> OutsideColumns(const VoxelGrid& grid, int floor, const PlaceFilter& seen,
                                    int gap_cells) {
  const int w = grid.dims.x(), h = grid.dims.y();
  const size_t n = static_cast<size_t>(w) * h;
  constexpr int kFar = std::numeric_limits<int>::max();
  std::vector<uint8_t> open(n, 0);
  std::vector<int> to_structure(n, kFar);
  std::vector<size_t> front;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      bool solid = false;
      for (int z = floor + 1; z < grid.dims.z() && !solid; ++z) solid = grid.At(x, y, z);
      const Eigen::Vector2d centre =
          grid.origin.head<2>() + grid.resolution * Eigen::Vector2d(x + 0.5, y + 0.5);
      open[i] = !solid && !seen(centre) ? 1 : 0;
      if (solid) {
        to_structure[i] = 0;
        front.push_back(i);
      }
    }
  }
  // Breadth first over 8 neighbours from `queue` into the cells `enter` allows, up to `limit`.
  const auto spread = [&](std::vector<int>& depth, std::vector<size_t>& queue,
                          const std::function<bool(size_t)>& enter, int limit) {
    for (size_t head = 0; head < queue.size(); ++head) {
      const size_t i = queue[head];
      if (depth[i] >= limit) continue;
      const int x = static_cast<int>(i % w), y = static_cast<int>(i / w);
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u < 0 || v < 0 || u >= w || v >= h) continue;
          const size_t j = static_cast<size_t>(v) * w + u;
          if (depth[j] <= depth[i] + 1 || !enter(j)) continue;
          depth[j] = depth[i] + 1;
          queue.push_back(j);
        }
      }
    }
  };
  spread(
      to_structure, front, [](size_t) { return true; }, gap_cells);
  const auto away_from_structure = [&](size_t i) {
    return open[i] != 0 && to_structure[i] > gap_cells;
  };
  std::vector<int> from_edge(n, kFar);
  front.clear();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      const bool edge = x == 0 || y == 0 || x == w - 1 || y == h - 1;
      if (edge && away_from_structure(i)) {
        from_edge[i] = 0;
        front.push_back(i);
      }
    }
  }
  spread(from_edge, front, away_from_structure, kFar - 1);
  std::vector<int> grown(n, kFar);
  front.clear();
  for (size_t i = 0; i < n; ++i) {
    if (from_edge[i] != kFar) {
      grown[i] = 0;
      front.push_back(i);
    }
  }
  spread(
      grown, front, [&](size_t i) { return open[i] != 0; }, gap_cells);
  std::vector<uint8_t> outside(n, 0);
  for (size_t i = 0; i < n; ++i) outside[i] = grown[i] != kFar ? 1 : 0;
  return outside;
}

// Greedy merge: grow each unvisited voxel into the largest box along x, then y, then z.
std::vector<BoxShape> MergeBoxes(VoxelGrid& grid, int z_begin, double z_shift) {
  std::vector<BoxShape> boxes;
  const Eigen::Vector3i& d = grid.dims;
  auto full = [&](int x0, int x1, int y0, int y1, int z0, int z1) {
    for (int z = z0; z < z1; ++z)
      for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
          if (!grid.At(x, y, z)) return false;
    return true;
  };
  for (int z = z_begin; z < d.z(); ++z) {
    for (int y = 0; y < d.y(); ++y) {
      for (int x = 0; x < d.x(); ++x) {
        if (!grid.At(x, y, z)) continue;
        int x1 = x + 1, y1 = y + 1, z1 = z + 1;
        while (x1 < d.x() && grid.At(x1, y, z)) ++x1;
        while (y1 < d.y() && full(x, x1, y1, y1 + 1, z, z + 1)) ++y1;
        while (z1 < d.z() && full(x, x1, y, y1, z1, z1 + 1)) ++z1;
        for (int zz = z; zz < z1; ++zz)
          for (int yy = y; yy < y1; ++yy)
            for (int xx = x; xx < x1; ++xx) grid.occupied[grid.Index(xx, yy, zz)] = 0;
        const double r = grid.resolution;
        BoxShape box;
        box.center = grid.origin.head<2>() + r * Eigen::Vector2d((x + x1) / 2.0, (y + y1) / 2.0);
        box.size = Eigen::Vector3d((x1 - x) * r, (y1 - y) * r, (z1 - z) * r);
        box.base_z = grid.origin.z() + z * r + z_shift;
        boxes.push_back(box);
      }
    }
  }
  return boxes;
}

void AddObjectsNearWalls(World& world, Rng& rng, const PlaceFilter& inside) {
  const Scene scene = Scene::Build(world);
  const std::vector<std::pair<std::string, Eigen::Vector3d>> items = {
      {"chair", {0.5, 0.5, 0.9}},
      {"chair", {0.5, 0.5, 0.9}},
      {"potted plant", {0.45, 0.45, 1.0}},
      {"potted plant", {0.45, 0.45, 1.0}},
      {"fire extinguisher", {0.2, 0.2, 0.6}},
      {"backpack", {0.35, 0.25, 0.5}},
      {"printer", {0.5, 0.45, 0.4}},
      {"bench", {1.5, 0.5, 0.45}},
      {"trash can", {0.4, 0.4, 0.7}},
      {"suitcase", {0.5, 0.3, 0.7}}};
  // Candidate spots: cells of the robot's largest free region inside the scanned building, so
  // every object is reachable.
  const GroundTruthGrid grid = ModalityGrid(world, Modality::kGround, 0.0);
  const std::vector<uint8_t> region = LargestFreeRegion(grid);
  std::vector<Eigen::Vector2d> spots;
  for (size_t c = 0; c < region.size(); ++c) {
    const Eigen::Vector2d spot =
        grid.CellCentre(static_cast<int>(c % grid.width), static_cast<int>(c / grid.width));
    if (region[c] != 0 && inside(spot)) spots.push_back(spot);
  }
  if (spots.empty()) return;
  for (const auto& [label, size] : items) {
    const double reach = std::hypot(size.x(), size.y()) / 2;
    for (int attempt = 0; attempt < 400; ++attempt) {
      const Eigen::Vector2d spot = spots[rng.UniformInt(0, static_cast<int>(spots.size()) - 1)];
      const BoxShape box = parts::Box(spot.x(), spot.y(), size.x(), size.y(), size.z(), 0.0);
      // Free where it stands, but with a wall within 0.6 m so it does not block a corridor.
      if (scene.SolidTouchingCylinder(box.center, reach + 0.05, 0.05, size.z())) continue;
      if (!scene.SolidTouchingCylinder(box.center, reach + 0.6, 0.05, size.z())) continue;
      bool apart = true;  // 1 m between added objects
      for (const ObjectInstance& o : world.objects)
        apart = apart && !FootprintsOverlap(box, o.box, 0.5);
      if (!apart) continue;
      parts::AddObject(world, label, Rgb{static_cast<uint8_t>(rng.UniformInt(60, 230)), 90, 150},
                       box, world.rooms.front().name);
      break;
    }
  }
}

}  // namespace

absl::StatusOr<World> OctomapWorld(const std::string& bt_path, const std::string& name,
                                   uint64_t seed, OctomapImport* stats) {
  auto tree = std::make_unique<octomap::OcTree>(0.1);
  if (!tree->readBinary(bt_path)) {
    return absl::NotFoundError(absl::StrCat("OctoMap not readable: ", bt_path));
  }
  // The finest-voxel raster of the map's bounds must fit a budget (FR-079: 3.6 M voxels); the
  // start and object placement after it walk the whole floor.
  constexpr double kMaxVoxels = 32.0 * 1024 * 1024;
  double x0, y0, z0, x1, y1, z1;
  tree->getMetricMin(x0, y0, z0);
  tree->getMetricMax(x1, y1, z1);
  const double r = tree->getResolution();
  const double voxels =
      std::ceil((x1 - x0) / r) * std::ceil((y1 - y0) / r) * std::ceil((z1 - z0) / r);
  constexpr double kMaxFloorM2 = 10000.0;  // 100 m x 100 m; FR-079 is about 0.06 of it
  const double floor_m2 = (x1 - x0) * (y1 - y0);
  if (!(r > 0.0) || !std::isfinite(voxels) || voxels < 1.0 || voxels > kMaxVoxels ||
      !(floor_m2 <= kMaxFloorM2)) {
    return absl::InvalidArgumentError(
        absl::StrCat("OctoMap ", bt_path, ": its bounds at ", r,
                     " m make no raster of at most 32 Mi voxels and 100 x 100 m"));
  }
  VoxelGrid grid = Rasterize(*tree);
  const int floor = FloorLayer(grid);
  // Found by fuzz_octomap_import: a map with nothing occupied below 0.5 m has no floor layer.
  if (floor < 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("OctoMap ", bt_path, ": no occupied floor layer below 0.5 m"));
  }
  const double floor_top = grid.origin.z() + (floor + 1) * grid.resolution;
  const PlaceFilter inside = SeenFloor(grid, floor, 3);
  // Before MergeBoxes, which empties the voxels it takes; gaps up to 1.2 m stay closed.
  VoxelGrid outside{
      grid.origin, grid.resolution, Eigen::Vector3i(grid.dims.x(), grid.dims.y(), 1),
      OutsideColumns(grid, floor, inside, static_cast<int>(std::ceil(0.6 / grid.resolution)))};
  int occupied = 0;
  for (int z = floor + 1; z < grid.dims.z(); ++z)
    for (int y = 0; y < grid.dims.y(); ++y)
      for (int x = 0; x < grid.dims.x(); ++x) occupied += grid.At(x, y, z) ? 1 : 0;
  World world;
  world.name = name;
  world.description = absl::StrCat("OctoMap ", bt_path.substr(bt_path.find_last_of('/') + 1),
                                   " as boxes, objects seeded ", seed);
  world.bounds_min = grid.origin.head<2>();
  world.bounds_max = grid.origin.head<2>() + grid.resolution * grid.dims.head<2>().cast<double>();
  world.floor_colour = Rgb{160, 160, 150};
  for (const BoxShape& box : MergeBoxes(grid, floor + 1, -floor_top)) {
    world.obstacles.push_back(Obstacle{"wall", kWallColour, box});
  }
  // As high as the scan's structure; 2 m when the map holds nothing above its floor.
  const double height =
      std::max(2.0, grid.resolution * static_cast<double>(grid.dims.z() - floor - 1));
  for (BoxShape box : MergeBoxes(outside, 0, 0.0)) {
    box.base_z = 0.0;
    box.size.z() = height;
    world.obstacles.push_back(Obstacle{"wall", kWallColour, box});
  }
  const Eigen::Vector2d lo = world.bounds_min, hi = world.bounds_max;
  // Nor does a scanned floor that runs to the edge of the bounds lead past it: a wall along the
  // inside of the edge (the world's boxes lie within its bounds).
  constexpr double kEdgeM = 0.1;
  const Eigen::Vector2d span = hi - lo;
  for (const auto& [centre, size] : std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>{
           {{lo.x() + span.x() / 2, lo.y() + kEdgeM / 2}, {span.x(), kEdgeM}},
           {{lo.x() + span.x() / 2, hi.y() - kEdgeM / 2}, {span.x(), kEdgeM}},
           {{lo.x() + kEdgeM / 2, lo.y() + span.y() / 2}, {kEdgeM, span.y()}},
           {{hi.x() - kEdgeM / 2, lo.y() + span.y() / 2}, {kEdgeM, span.y()}}}) {
    BoxShape edge;
    edge.center = centre;
    edge.size = Eigen::Vector3d(size.x(), size.y(), height);
    world.obstacles.push_back(Obstacle{"wall", kWallColour, edge});
  }
  world.rooms.push_back(
      Room{"building_1",
           "corridor",
           {{lo.x(), lo.y()}, {hi.x(), lo.y()}, {hi.x(), hi.y()}, {lo.x(), hi.y()}}});
  Rng rng(seed);
  AddObjectsNearWalls(world, rng, inside);
  RemoveUnreachableObjects(world, Modality::kGround, 0.0);
  world.starts = ChooseStarts(world, Modality::kGround, 0.0, 5, rng, inside);
  if (stats != nullptr) {
    *stats = OctomapImport{static_cast<int>(world.obstacles.size()), occupied, floor_top};
  }
  return world;
}

}  // namespace semnav::sim
