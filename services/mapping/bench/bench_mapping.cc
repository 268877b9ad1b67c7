// semnav-bench-mapping: frame integration vs plain OctoMap, agreement, FR-079 grid, scene graph.
// Usage: semnav-bench-mapping [--json FILE] [--png FILE] [--benchmark_* flags]
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <string>
#include <vector>

#include "services/common/cli/benchmark_flags.h"
#include "services/common/cli/help.h"
#include "services/mapping/bench/figures.h"
#include "services/mapping/bench/grid_image.h"
#include "services/mapping/core/climbing.h"
#include "services/mapping/core/depth_projection.h"
#include "services/mapping/core/mapping_engine.h"
#include "services/mapping/core/octomap_integrator.h"
#include "services/mapping/core/octree_agreement.h"
#include "services/mapping/core/scan_matcher.h"
#include "services/mapping/core/scene_graph.h"
#include "services/mapping/testing/synthetic_room.h"

namespace semnav::mapping::bench {
namespace {

constexpr int kTourFrames = 8;
std::string g_png_path;

double ThreadCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

double MsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

const std::vector<SensorFrame>& Tour() {
  static const std::vector<SensorFrame> frames = [] {
    const testing::SyntheticRoom room = testing::StandardRoom();
    std::vector<SensorFrame> out;
    int64_t stamp = 0;
    for (const CameraPose& pose : testing::RoomTour(room, kTourFrames)) {
      out.push_back(
          testing::RenderFrame(room, pose, stamp += 100'000'000, DepthEncoding::kMillimetres16U));
    }
    return out;
  }();
  return frames;
}

std::vector<Eigen::Vector3f> Points(const SensorFrame& frame) {
  return ProjectDepth(DecodeDepth(frame.depth), frame.intrinsics, frame.pose, DepthRange{}, 1);
}

octomap::Pointcloud ToCloud(const std::vector<Eigen::Vector3f>& points) {
  octomap::Pointcloud cloud;
  cloud.reserve(points.size());
  for (const Eigen::Vector3f& p : points) cloud.push_back(p.x(), p.y(), p.z());
  return cloud;
}

// One 640x480 frame: decode + back-project + OctomapIntegrator (2 threads), into a growing map.
void BM_FrameIntegration(benchmark::State& state) {
  octomap::OcTree tree(0.05);
  const OctomapIntegrator integrator(2);
  size_t i = 0;
  for (auto _ : state) {
    const SensorFrame& frame = Tour()[i++ % Tour().size()];
    const auto start = std::chrono::steady_clock::now();
    integrator.Integrate(tree, Points(frame), frame.pose.position.cast<float>());
    const double ms = MsSince(start);
    state.SetIterationTime(ms / 1000.0);
    Collected().samples_ms["frame_ms"].push_back(ms);
  }
}
BENCHMARK(BM_FrameIntegration)
    ->UseManualTime()
    ->Iterations(3 * kTourFrames)
    ->Unit(benchmark::kMillisecond);

// The same frames through OctoMap's plain insertPointCloud (every ray, no discretization).
void BM_PlainInsertPointCloud(benchmark::State& state) {
  octomap::OcTree tree(0.05);
  size_t i = 0;
  for (auto _ : state) {
    const SensorFrame& frame = Tour()[i++ % Tour().size()];
    const auto start = std::chrono::steady_clock::now();
    const Eigen::Vector3d& o = frame.pose.position;
    tree.insertPointCloud(ToCloud(Points(frame)), octomap::point3d(o.x(), o.y(), o.z()),
                          DepthRange{}.max_m);
    const double ms = MsSince(start);
    state.SetIterationTime(ms / 1000.0);
    Collected().samples_ms["octomap_insert_ms"].push_back(ms);
  }
}
BENCHMARK(BM_PlainInsertPointCloud)
    ->UseManualTime()
    ->Iterations(kTourFrames)
    ->Unit(benchmark::kMillisecond);

// Whole MappingEngine::AddFrame (integration + columns + Bayesian grid + scene graph).
void BM_EngineFrame(benchmark::State& state) {
  MappingEngine engine{MappingConfig{}};
  size_t i = 0;
  for (auto _ : state) {
    SensorFrame frame = Tour()[i % Tour().size()];
    frame.stamp_ns = static_cast<int64_t>(++i) * 100'000'000;
    const auto start = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(engine.AddFrame(frame));
    const double ms = MsSince(start);
    state.SetIterationTime(ms / 1000.0);
    Collected().samples_ms["engine_frame_ms"].push_back(ms);
  }
}
BENCHMARK(BM_EngineFrame)
    ->UseManualTime()
    ->Iterations(2 * kTourFrames)
    ->Unit(benchmark::kMillisecond);

// FR-079: load the .bt, voxel columns, h_f/h_c estimate, climbing + grid, all layers rendered.
void BM_Fr079Grid(benchmark::State& state) {
  const std::string path =
      std::string(SEMNAV_SHARED_DATA_DIR) + "/pointclouds-octomaps/octomap_share/geb079.bt";
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const octomap::OcTree tree(path);
    const VoxelColumns columns = VoxelColumns::FromOctree(tree);
    HierarchicalGridConfig config;
    config.resolution_m = 0.04;
    HierarchicalGrid grid(config, EstimateHeights(columns).value_or(ClimbingHeights{}));
    absl::flat_hash_set<VoxelColumns::ColumnId> all;
    for (const auto& [id, column] : columns.columns()) all.insert(id);
    grid.Update(columns, all);
    const GridLayers layers = RenderLayers(grid, FullWindow(grid), GridLayersConfig{});
    const double ms = MsSince(start);
    state.SetIterationTime(ms / 1000.0);
    Collected().samples_ms["fr079_grid_ms"].push_back(ms);
    Collected().values["rss_mb_fr079"] =
        std::max(Collected().values["rss_mb_fr079"], ResidentMiB());
    if (!g_png_path.empty()) cv::imwrite(g_png_path, RenderGridImage(layers));
  }
}
BENCHMARK(BM_Fr079Grid)->UseManualTime()->Iterations(3)->Unit(benchmark::kMillisecond);

// FR-079's grid at mapping's 5 cm as the scan matcher's raster: occupied = obstacle or
// structure, opaque = structure, observed free = the robot may stand there.
const OccupiedRaster& Fr079Raster() {
  static const OccupiedRaster raster = [] {
    const octomap::OcTree tree(std::string(SEMNAV_SHARED_DATA_DIR) +
                               "/pointclouds-octomaps/octomap_share/geb079.bt");
    const VoxelColumns columns = VoxelColumns::FromOctree(tree);
    HierarchicalGrid grid(HierarchicalGridConfig{},
                          EstimateHeights(columns).value_or(ClimbingHeights{}));
    absl::flat_hash_set<VoxelColumns::ColumnId> all;
    for (const auto& [id, column] : columns.columns()) all.insert(id);
    grid.Update(columns, all);
    return GridRaster(grid, FullWindow(grid), /*free_and_opaque=*/true);
  }();
  return raster;
}

// What a 360 deg depth turn at `robot` sees: the first occupied cell along 720 rays within 8 m.
std::vector<Eigen::Vector2d> TurnScan(const OccupiedRaster& map, const Eigen::Vector2d& robot) {
  std::vector<Eigen::Vector2d> hits;
  for (int i = 0; i < 720; ++i) {
    const double angle = 2.0 * M_PI * i / 720;
    for (double r = 0.3; r < 8.0; r += map.resolution / 2) {
      const Eigen::Vector2d p = robot + r * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      const int col = static_cast<int>(std::floor((p.x() - map.origin_x) / map.resolution));
      const int row = static_cast<int>(std::floor((p.y() - map.origin_y) / map.resolution));
      if (col < 0 || row < 0 || col >= map.width || row >= map.height) break;
      if (map.occupied[static_cast<size_t>(row) * map.width + col] != 0) {
        hits.push_back(p);
        break;
      }
    }
  }
  return hits;
}

// The lost-robot scan match on FR-079 (one floor of a real building): from free cells spread
// over the map, the scan a turn sees, in a frame 3 m and 100 deg off. Local: a coarse pose 0.2 m
// and 5 deg off the truth. Global: no coarse pose. Counts the answers within 0.1 m / 1 deg.
void BM_LostScanMatchFr079(benchmark::State& state) {
  const bool global = state.range(0) != 0;
  const OccupiedRaster& map = Fr079Raster();
  std::vector<Eigen::Vector2d> free_cells;
  for (int row = 0; row < map.height; row += 40) {
    for (int col = 0; col < map.width; col += 40) {
      if (map.observed_free[static_cast<size_t>(row) * map.width + col] != 0) {
        free_cells.emplace_back(map.origin_x + (col + 0.5) * map.resolution,
                                map.origin_y + (row + 0.5) * map.resolution);
      }
    }
  }
  const PlanarCorrection truth{3.0, -1.0, 100.0 * M_PI / 180.0};
  const PlanarCorrection reported_from_map = truth.Inverse();
  size_t i = 0;
  int right = 0;
  int runs = 0;
  for (auto _ : state) {
    const Eigen::Vector2d robot = free_cells[(i++ * 7) % free_cells.size()];
    std::vector<Eigen::Vector2d> scan;
    for (const Eigen::Vector2d& p : TurnScan(map, robot))
      scan.push_back(reported_from_map.Apply(p));
    const Eigen::Vector2d robot_reported = reported_from_map.Apply(robot);
    // Off by 0.2 m / -0.1 m and 5 deg at the robot (the turn about the robot, not the origin).
    const PlanarCorrection turn{0.0, 0.0, 5.0 * M_PI / 180.0};
    const Eigen::Vector2d shift = robot - turn.Apply(robot) + Eigen::Vector2d(0.2, -0.1);
    const PlanarCorrection coarse = PlanarCorrection{shift.x(), shift.y(), turn.yaw}.After(truth);
    const auto start = std::chrono::steady_clock::now();
    const absl::StatusOr<ScanMatchResult> result =
        global
            ? MatchScanGlobally(map, scan, robot_reported, ScanMatchConfig{}, GlobalMatchConfig{})
            : MatchScan(map, scan, coarse, ScanMatchConfig{});
    const double ms = MsSince(start);
    state.SetIterationTime(ms / 1000.0);
    Collected().samples_ms[global ? "global_scan_match_ms" : "scan_match_ms"].push_back(ms);
    ++runs;
    if (result.ok() && result->refined &&
        (result->correction.Apply(robot_reported) - robot).norm() <= 0.1 &&
        std::abs(std::remainder(result->correction.yaw - truth.yaw, 2.0 * M_PI)) <= M_PI / 180.0) {
      ++right;
    }
  }
  Collected().values[global ? "global_scan_match_right" : "scan_match_right"] =
      static_cast<double>(right) / std::max(runs, 1);
}
BENCHMARK(BM_LostScanMatchFr079)
    ->Arg(0)
    ->Arg(1)
    ->UseManualTime()
    ->Iterations(12)
    ->Unit(benchmark::kMillisecond);

// 20 detections (re-observations with jittered position and 512-d embedding) into a 500-object
// graph.
void BM_SceneGraphUpdate(benchmark::State& state) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(0.0, 40.0);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  auto embedding = [&] {
    std::vector<float> e(512);
    for (float& x : e) x = gauss(rng);
    return e;
  };
  const std::vector<std::string> labels{"chair", "table", "sofa", "bed",
                                        "tv",    "plant", "sink", "toilet"};
  SceneGraphConfig config;
  config.prune_single_after_s = 1e9;
  SceneGraph graph(config);
  std::vector<ObjectObservation> seeds;
  for (int i = 0; i < 500; ++i) {
    ObjectObservation o;
    o.label = labels[static_cast<size_t>(i) % labels.size()];
    o.position = {coord(rng), coord(rng), 0.5};
    o.size = {0.5, 0.5, 0.8};
    o.score = 0.8;
    o.embedding = embedding();
    seeds.push_back(o);
  }
  graph.Integrate(seeds, 0);
  int64_t now = 0;
  for (auto _ : state) {
    std::vector<ObjectObservation> batch;
    for (int k = 0; k < 20; ++k) {
      ObjectObservation o = seeds[std::uniform_int_distribution<size_t>(0, seeds.size() - 1)(rng)];
      o.position += Eigen::Vector3d(0.05, -0.05, 0.0);
      for (float& x : o.embedding) x += 0.1f * gauss(rng);
      o.stamp_ns = now;
      batch.push_back(std::move(o));
    }
    now += 100'000'000;
    const double cpu_start = ThreadCpuMs();
    const auto start = std::chrono::steady_clock::now();
    graph.Integrate(batch, now);
    const double ms = MsSince(start);
    state.SetIterationTime(ms / 1000.0);
    Collected().samples_ms["scene_graph_update_ms"].push_back(ms);
    // Single-threaded: its CPU time is the work itself, free of waits for a busy core.
    Collected().samples_ms["scene_graph_update_cpu_ms"].push_back(ThreadCpuMs() - cpu_start);
  }
  Collected().values["scene_graph_objects_after"] = static_cast<double>(graph.objects().size());
}
BENCHMARK(BM_SceneGraphUpdate)->UseManualTime()->Iterations(500)->Unit(benchmark::kMillisecond);

// Agreement of the fast path with plain insertPointCloud over one tour (not timed).
void MeasureAgreement() {
  octomap::OcTree reference(0.05);
  octomap::OcTree fast(0.05);
  const OctomapIntegrator integrator(2);
  for (const SensorFrame& frame : Tour()) {
    const std::vector<Eigen::Vector3f> points = Points(frame);
    const Eigen::Vector3d& o = frame.pose.position;
    reference.insertPointCloud(ToCloud(points), octomap::point3d(o.x(), o.y(), o.z()),
                               DepthRange{}.max_m);
    integrator.Integrate(fast, points, o.cast<float>());
  }
  const OctreeAgreement agreement = CompareOctrees(reference, fast);
  Collected().values["occupied_agreement"] = agreement.occupied;
  Collected().values["free_agreement"] = agreement.free;
}

}  // namespace
}  // namespace semnav::mapping::bench

int main(int argc, char** argv) {
  constexpr char kUsage[] =
      "usage: semnav-bench-mapping [--json FILE] [--png FILE] [--benchmark_* flags]\n"
      "Frame integration vs plain OctoMap, agreement, FR-079 grid, scene-graph update.\n";
  using namespace semnav::mapping::bench;
  const semnav::ParsedFlags flags = semnav::ParseBenchmarkFlagsOrExit(
      &argc, argv, {{"json", "FILE", ""}, {"png", "FILE", ""}}, "semnav-bench-mapping", kUsage);
  const std::string json_path = flags.Get("json").value_or("");
  if (auto png = flags.Get("png")) g_png_path = *png;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  MeasureAgreement();

  Figures& f = Collected();
  nlohmann::json out;
  out["frame_ms_median"] = Median(f.samples_ms["frame_ms"]);
  out["octomap_insert_ms_median"] = Median(f.samples_ms["octomap_insert_ms"]);
  out["engine_frame_ms_median"] = Median(f.samples_ms["engine_frame_ms"]);
  out["occupied_agreement"] = f.values["occupied_agreement"];
  out["free_agreement"] = f.values["free_agreement"];
  out["fr079_grid_ms"] = Median(f.samples_ms["fr079_grid_ms"]);
  out["scene_graph_update_ms_p99"] = Percentile(f.samples_ms["scene_graph_update_ms"], 0.99);
  out["scene_graph_update_ms_median"] = Median(f.samples_ms["scene_graph_update_ms"]);
  out["scene_graph_update_cpu_ms_p99"] =
      Percentile(f.samples_ms["scene_graph_update_cpu_ms"], 0.99);
  out["rss_mb_fr079"] = f.values["rss_mb_fr079"];
  out["scan_match_ms_median"] = Median(f.samples_ms["scan_match_ms"]);
  out["scan_match_right"] = f.values["scan_match_right"];
  out["global_scan_match_ms_median"] = Median(f.samples_ms["global_scan_match_ms"]);
  out["global_scan_match_right"] = f.values["global_scan_match_right"];
  std::printf("\n%-30s %12s %s\n", "figure", "value", "target");
  const std::map<std::string, std::string> targets{{"frame_ms_median", "<= 40 ms"},
                                                   {"occupied_agreement", ">= 0.98"},
                                                   {"free_agreement", ">= 0.95"},
                                                   {"scene_graph_update_ms_p99", "<= 1 ms"}};
  for (const auto& [name, value] : out.items()) {
    const auto target = targets.find(name);
    std::printf("%-30s %12.4f %s\n", name.c_str(), value.get<double>(),
                target == targets.end() ? "" : target->second.c_str());
  }
  if (!json_path.empty()) std::ofstream(json_path) << out.dump(2) << "\n";
  return 0;
}
