#include "services/mapping/core/octomap_integrator.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>

#include "services/mapping/core/octree_batch_update.h"

namespace semnav::mapping {
namespace {

// Axis-aligned key box of one scan with a dense index over it.
struct KeyBox {
  std::array<int, 3> lo{};
  std::array<int, 3> size{};

  static KeyBox Around(const std::vector<octomap::OcTreeKey>& keys) {
    std::array<int, 3> lo{keys[0][0], keys[0][1], keys[0][2]};
    std::array<int, 3> hi = lo;
    for (const octomap::OcTreeKey& k : keys) {
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min<int>(lo[a], k[a]);
        hi[a] = std::max<int>(hi[a], k[a]);
      }
    }
    KeyBox box;
    box.lo = lo;
    for (int a = 0; a < 3; ++a) box.size[a] = hi[a] - lo[a] + 1;
    return box;
  }
  size_t Cells() const { return static_cast<size_t>(size[0]) * size[1] * size[2]; }
  size_t Index(const std::array<int, 3>& k) const {
    return (static_cast<size_t>(k[2] - lo[2]) * size[1] + (k[1] - lo[1])) * size[0] +
           (k[0] - lo[0]);
  }
  size_t Index(const octomap::OcTreeKey& k) const {
    return Index(std::array<int, 3>{k[0], k[1], k[2]});
  }
  octomap::OcTreeKey KeyAt(size_t index) const {
    const auto x = static_cast<int>(index % size[0]);
    const auto y = static_cast<int>((index / size[0]) % size[1]);
    const auto z = static_cast<int>(index / (static_cast<size_t>(size[0]) * size[1]));
    return octomap::OcTreeKey(static_cast<octomap::key_type>(lo[0] + x),
                              static_cast<octomap::key_type>(lo[1] + y),
                              static_cast<octomap::key_type>(lo[2] + z));
  }
};

// One bit per voxel of a KeyBox.
class VoxelBits {
 public:
  explicit VoxelBits(size_t cells) : words_((cells + 63) / 64, 0) {}
  void Set(size_t i) { words_[i >> 6] |= uint64_t{1} << (i & 63); }
  bool TestAndSet(size_t i) {
    uint64_t& word = words_[i >> 6];
    const uint64_t mask = uint64_t{1} << (i & 63);
    const bool was_set = (word & mask) != 0;
    word |= mask;
    return was_set;
  }
  bool Test(size_t i) const { return (words_[i >> 6] >> (i & 63)) & 1; }
  uint64_t Word(size_t w) const { return words_[w]; }
  size_t Words() const { return words_.size(); }

 private:
  std::vector<uint64_t> words_;
};

// Walks the voxels from the endpoint voxel (excluded) back to the sensor voxel (included) with a 3D
// DDA in key units (the voxels OctoMap's computeRayKeys visits) and marks them in `passed`. The
// walk aims at the sensor's key and never leaves the box: origin_units / resolution can round to
// the neighbour of the key OctoMap computed (a sensor at x = 1.0 m), and a walk aimed there used
// to step one voxel past the box and write outside `passed`.
void CarveRay(const Eigen::Vector3d& origin_units, const octomap::OcTreeKey& origin_key,
              const octomap::OcTreeKey& endpoint, const KeyBox& box, VoxelBits& passed) {
  std::array<int, 3> voxel{endpoint[0], endpoint[1], endpoint[2]};
  const Eigen::Vector3d dir =
      origin_units - Eigen::Vector3d(voxel[0] + 0.5, voxel[1] + 0.5, voxel[2] + 0.5);
  std::array<int, 3> step{};
  std::array<double, 3> t_max{};
  std::array<double, 3> t_delta{};
  int steps_left = 0;
  for (int a = 0; a < 3; ++a) {
    const int target = origin_key[a];
    steps_left += std::abs(target - voxel[a]);
    if (target == voxel[a] || dir[a] == 0.0) {
      t_max[a] = t_delta[a] = std::numeric_limits<double>::infinity();
      continue;
    }
    step[a] = target > voxel[a] ? 1 : -1;
    t_delta[a] = std::abs(1.0 / dir[a]);
    t_max[a] = 0.5 * t_delta[a];  // the walk starts at a voxel centre
  }
  while (steps_left-- > 0) {
    int a = t_max[0] < t_max[1] ? (t_max[0] < t_max[2] ? 0 : 2) : (t_max[1] < t_max[2] ? 1 : 2);
    // An axis already at the sensor's key is done; move along one that is not.
    if (voxel[a] == origin_key[a]) {
      a = voxel[0] != origin_key[0] ? 0 : (voxel[1] != origin_key[1] ? 1 : 2);
      if (voxel[a] == origin_key[a]) return;
      step[a] = origin_key[a] > voxel[a] ? 1 : -1;
    }
    voxel[a] += step[a];
    t_max[a] += t_delta[a];
    if (voxel[a] < box.lo[a] || voxel[a] >= box.lo[a] + box.size[a]) return;
    passed.Set(box.Index(voxel));
  }
}

}  // namespace

std::vector<TouchedVoxel> OctomapIntegrator::Integrate(octomap::OcTree& tree,
                                                       const std::vector<Eigen::Vector3f>& points,
                                                       const Eigen::Vector3f& origin) const {
  return ApplyVoxelUpdates(tree, CastScan(tree, points, origin));
}

std::vector<VoxelUpdate> OctomapIntegrator::CastScan(const octomap::OcTree& tree,
                                                     const std::vector<Eigen::Vector3f>& points,
                                                     const Eigen::Vector3f& origin) const {
  octomap::OcTreeKey origin_key;
  if (points.empty() ||
      !tree.coordToKeyChecked(octomap::point3d(origin.x(), origin.y(), origin.z()), origin_key)) {
    return {};
  }
  std::vector<octomap::OcTreeKey> keys{origin_key};
  keys.reserve(points.size() + 1);
  for (const Eigen::Vector3f& p : points) {
    octomap::OcTreeKey k;
    if (tree.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), k)) keys.push_back(k);
  }
  const KeyBox box = KeyBox::Around(keys);

  // Distinct endpoint voxels: each is hit once per scan, like OctoMap's discretized update.
  VoxelBits hit(box.Cells());
  std::vector<octomap::OcTreeKey> endpoints;
  endpoints.reserve(keys.size());
  for (size_t i = 1; i < keys.size(); ++i) {
    if (!hit.TestAndSet(box.Index(keys[i]))) endpoints.push_back(keys[i]);
  }

  // Sensor position in key units (voxel i spans [i, i + 1)).
  const double resolution = tree.getResolution();
  const Eigen::Vector3d origin_units =
      origin.cast<double>() / resolution +
      Eigen::Vector3d::Constant(static_cast<double>(1u << (tree.getTreeDepth() - 1)));
  std::vector<VoxelBits> passed(static_cast<size_t>(threads_), VoxelBits(box.Cells()));
  std::vector<std::thread> workers;
  const size_t per_thread = (endpoints.size() + threads_ - 1) / threads_;
  for (int t = 0; t < threads_; ++t) {
    const size_t begin = std::min(endpoints.size(), t * per_thread);
    const size_t end = std::min(endpoints.size(), begin + per_thread);
    workers.emplace_back([&, t, begin, end] {
      for (size_t i = begin; i < end; ++i) {
        CarveRay(origin_units, origin_key, endpoints[i], box, passed[t]);
      }
    });
  }
  for (std::thread& w : workers) w.join();

  std::vector<VoxelUpdate> updates;
  updates.reserve(endpoints.size() * 16);
  for (size_t w = 0; w < hit.Words(); ++w) {
    uint64_t any = hit.Word(w);
    for (const VoxelBits& bits : passed) any |= bits.Word(w);
    for (; any != 0; any &= any - 1) {
      const size_t i = w * 64 + static_cast<size_t>(__builtin_ctzll(any));
      updates.push_back({box.KeyAt(i), hit.Test(i)});
    }
  }
  return updates;
}

}  // namespace semnav::mapping
