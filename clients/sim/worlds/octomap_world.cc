#include "clients/sim/worlds/octomap_world.h"

#include <octomap/OcTree.h>

#include <cmath>
#include <memory>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/core/scene.h"
#include "clients/sim/worlds/scene_parts.h"
#include "clients/sim/worlds/start_poses.h"

namespace semnav::sim {
namespace {

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
    world.obstacles.push_back(Obstacle{"wall", Rgb{205, 200, 190}, box});
  }
  const Eigen::Vector2d lo = world.bounds_min, hi = world.bounds_max;
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
