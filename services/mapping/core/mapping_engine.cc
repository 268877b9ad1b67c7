#include "services/mapping/core/mapping_engine.h"

#include <algorithm>
#include <cctype>
#include <deque>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "services/common/status/field_error.h"
#include "services/common/status/value_checks.h"
#include "services/mapping/core/frame_validation.h"
#include "services/mapping/core/map_serialization.h"
#include "services/mapping/core/object_visibility.h"
#include "services/mapping/core/semantic_filters.h"

namespace semnav::mapping {

struct MappingEngine::State {
  explicit State(const MappingConfig& config)
      : tree(std::make_unique<octomap::OcTree>(config.octomap_resolution_m)),
        columns(config.octomap_resolution_m),
        grid(config.grid, config.heights),
        semantic(config.semantic),
        scene(config.scene) {}

  // Replaces the geometry and semantics by `content`; the scene graph keeps its revision history.
  void Adopt(MapContent content, const MappingConfig& config) {
    tree = std::move(content.tree);
    columns = VoxelColumns::FromOctree(*tree);
    grid = HierarchicalGrid(config.grid, config.heights);
    if (content.grid && content.grid->resolution_m == config.grid.resolution_m) {
      // The saved log-odds: a rebuild from the octree would apply one update per cell.
      std::vector<HierarchicalGrid::CellState> cells;
      cells.reserve(content.grid->cells.size());
      for (const SavedGridCell& c : content.grid->cells) {
        cells.push_back({CellIndex{c.x, c.y}, c.log_odds, c.height, c.structure});
      }
      grid.RestoreCells(cells);
    } else {  // maps saved without the grid, or at another grid resolution
      absl::flat_hash_set<VoxelColumns::ColumnId> all;
      for (const auto& [id, column] : columns.columns()) all.insert(id);
      grid.Update(columns, all);
    }
    semantic.Clear();
    for (const auto& [label, points] : content.semantic_points) semantic.Add(label, points);
    scene.Replace(std::move(content.objects), content.next_object_id);
    last_stamp.clear();
    pose_untrusted.clear();
    lost_scans.clear();
    recent_walls.clear();
    embedding_dim = 0;
    for (const SceneObject& o : scene.objects()) {
      if (!o.embedding.empty()) embedding_dim = static_cast<int>(o.embedding.size());
    }
  }

  std::unique_ptr<octomap::OcTree> tree;
  VoxelColumns columns;
  HierarchicalGrid grid;
  SemanticMap semantic;
  SceneGraph scene;
  absl::flat_hash_map<std::string, int64_t> last_stamp;
  absl::flat_hash_map<std::string, bool> pose_untrusted;  // per robot: its last frame's flag
  // Per robot while its frames are untrusted: the obstacle cells (reported frame) they showed,
  // kept for MatchLostScan instead of entering the map.
  struct LostScan {
    absl::flat_hash_set<CellIndex> cells;
    Eigen::Vector2d robot = Eigen::Vector2d::Zero();  // the latest frame's camera, reported
    // Cells the robot's own frames turned occupied in the lookback before it reported the loss:
    // drawn at the pose it wrongly believed, so its matches do not count them as walls.
    absl::flat_hash_set<CellIndex> own_walls;
  };
  absl::flat_hash_map<std::string, LostScan> lost_scans;
  // Per robot: the cells each of its trusted frames turned occupied, for the lookback
  // (SceneGraphConfig::untrusted_lookback_s), at most lost_scan_max_cells in all.
  struct RecentWalls {
    std::deque<std::pair<int64_t, std::vector<CellIndex>>> frames;
    size_t cells = 0;
  };
  absl::flat_hash_map<std::string, RecentWalls> recent_walls;
  int embedding_dim = 0;
  std::deque<std::pair<uint64_t, GridWindow>> grid_changes;
  uint64_t grid_forgotten_before = 0;
  int accepted_frames = 0;
};

namespace {

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

GridWindow Union(const GridWindow& a, const GridWindow& b) {
  if (a.width == 0) return b;
  if (b.width == 0) return a;
  const int min_x = std::min(a.min.x, b.min.x);
  const int min_y = std::min(a.min.y, b.min.y);
  const int max_x = std::max(a.min.x + a.width, b.min.x + b.width);
  const int max_y = std::max(a.min.y + a.height, b.min.y + b.height);
  return {{min_x, min_y}, max_x - min_x, max_y - min_y};
}

}  // namespace

MappingEngine::MappingEngine(const MappingConfig& config)
    : config_(config),
      integrator_(config.threads),
      key_space_(config.octomap_resolution_m),
      state_(std::make_unique<State>(config)) {}

MappingEngine::~MappingEngine() = default;

ValidationContext MappingEngine::ContextFor(const std::string& robot_id) const {
  ValidationContext context;
  const State& s = *state_;
  if (const auto it = s.last_stamp.find(robot_id); it != s.last_stamp.end())
    context.last_stamp_ns = it->second;
  context.embedding_dim = s.embedding_dim;
  return context;
}

absl::StatusOr<FrameResult> MappingEngine::AddFrame(const SensorFrame& frame) {
  ValidationContext context;
  {
    absl::ReaderMutexLock lock(&mu_);
    context = ContextFor(frame.robot_id);
  }
  if (absl::Status status = ValidateFrame(frame, context); !status.ok()) return status;

  // The frame's own work runs outside the lock: decoding, projection, ray casting (most of a
  // frame's cost) and lifting the detections. Frames of different robots then prepare in
  // parallel, and grid fetches and queries wait only for the map update itself.
  FrameResult result;
  if (!frame.rgb_encoded.empty()) {
    const cv::Mat encoded(1, static_cast<int>(frame.rgb_encoded.size()), CV_8U,
                          const_cast<char*>(frame.rgb_encoded.data()));
    const cv::Mat gray = cv::imdecode(encoded, cv::IMREAD_GRAYSCALE);
    if (gray.empty()) return InvalidField("rgb.data", "not a decodable PNG or JPEG image");
    result.blurred = LaplacianVariance(gray) < config_.blur_min_laplacian_variance;
  }
  const cv::Mat depth = DecodeDepth(frame.depth);
  std::vector<Eigen::Vector3f> points =
      ProjectDepth(depth, frame.intrinsics, frame.pose, config_.range, config_.pixel_stride);
  const Eigen::Matrix3f rotation = frame.pose.orientation.toRotationMatrix().cast<float>();
  const Eigen::Vector3f origin = frame.pose.position.cast<float>();
  for (const Eigen::Vector3f& p : frame.lidar_points) {
    const float range = p.norm();
    if (range >= config_.range.min_m && range <= config_.range.max_m)
      points.push_back(rotation * p + origin);
  }
  // A frame whose pose the robot does not trust stays out of the occupancy map: at a wrong pose
  // it would draw walls where there are none, and a lost robot's look-around would then match
  // its own frames (as landmarks did: docs/performance/mission.md, "Losing the pose").
  std::vector<VoxelUpdate> updates;
  if (!frame.pose_untrusted) updates = integrator_.CastScan(key_space_, points, origin);
  std::vector<std::pair<const Detection*, LiftedDetection>> lifted_detections;
  if (!result.blurred) {
    for (const Detection& detection : frame.detections) {
      std::optional<LiftedDetection> lifted =
          LiftDetection(detection, depth, frame.intrinsics, frame.pose, config_.range, config_.lift,
                        frame.stamp_ns, frame.robot_id);
      if (lifted) lifted_detections.emplace_back(&detection, *std::move(lifted));
    }
  }

  absl::MutexLock lock(&mu_);
  State& s = *state_;
  // Another frame may have moved this robot's stamp or fixed the embedding length meanwhile.
  const ValidationContext now = ContextFor(frame.robot_id);
  if (now.last_stamp_ns != context.last_stamp_ns || now.embedding_dim != context.embedding_dim) {
    if (absl::Status status = ValidateFrame(frame, now); !status.ok()) return status;
  }
  const std::vector<TouchedVoxel> touched = ApplyVoxelUpdates(*s.tree, std::move(updates));
  result.voxels_updated = static_cast<uint32_t>(touched.size());
  const absl::flat_hash_set<VoxelColumns::ColumnId> columns = s.columns.Apply(touched);
  std::vector<CellIndex> turned_occupied;
  s.grid.Update(s.columns, columns, &turned_occupied);
  // The robot reports its loss: its frames of the lookback before it were at the wrong pose too.
  const bool new_loss = frame.pose_untrusted && !s.pose_untrusted[frame.robot_id];
  const int64_t lookback_ns = static_cast<int64_t>(config_.scene.untrusted_lookback_s * 1e9);
  if (frame.pose_untrusted) {
    State::LostScan& lost = s.lost_scans[frame.robot_id];
    if (new_loss) {
      lost.cells.clear();
      lost.own_walls.clear();
      if (const auto recent = s.recent_walls.find(frame.robot_id); recent != s.recent_walls.end()) {
        for (const auto& [stamp_ns, cells] : recent->second.frames) {
          if (stamp_ns >= frame.stamp_ns - lookback_ns)
            lost.own_walls.insert(cells.begin(), cells.end());
        }
        s.recent_walls.erase(recent);
      }
    }
    lost.robot = frame.pose.position.head<2>();
    absl::flat_hash_set<CellIndex>& scan = lost.cells;
    const ClimbingHeights& heights = s.grid.heights();
    for (const Eigen::Vector3f& p : points) {
      if (scan.size() >= config_.lost_scan_max_cells) break;
      // Obstacles only: the floor (and what lies on it within 10 cm) and the ceiling match
      // everywhere.
      if (p.z() < heights.foot_m + 0.1 || p.z() > heights.ceiling_m) continue;
      scan.insert(s.grid.CellOf(p.x(), p.y()));
    }
  } else {
    s.lost_scans.erase(frame.robot_id);
    State::RecentWalls& recent = s.recent_walls[frame.robot_id];
    if (!turned_occupied.empty()) {
      recent.cells += turned_occupied.size();
      recent.frames.emplace_back(frame.stamp_ns, std::move(turned_occupied));
    }
    while (!recent.frames.empty() && (recent.frames.front().first < frame.stamp_ns - lookback_ns ||
                                      recent.cells > config_.lost_scan_max_cells)) {
      recent.cells -= recent.frames.front().second.size();
      recent.frames.pop_front();
    }
  }

  std::vector<ObjectObservation> observations;
  for (auto& [detection, lifted] : lifted_detections) {
    observations.push_back(std::move(lifted.observation));
    if (!detection->embedding.empty())
      s.embedding_dim = static_cast<int>(detection->embedding.size());
  }
  result.detections_used = static_cast<uint32_t>(observations.size());
  if (new_loss) s.scene.MarkPoseUntrustedSince(frame.stamp_ns - lookback_ns);
  s.pose_untrusted[frame.robot_id] = frame.pose_untrusted;
  for (ObjectObservation& observation : observations)
    observation.pose_untrusted = frame.pose_untrusted;
  // Negative evidence only from what the robot trusts and its detector really looked at.
  const bool evidence = frame.detector_ran && !frame.pose_untrusted && !result.blurred;
  const std::vector<SceneObject> removed =
      s.scene.Integrate(observations, frame.stamp_ns, [&](const SceneObject& object) {
        return evidence &&
               ExpectedInView(object, depth, frame.intrinsics, frame.pose, config_.scene.existence);
      });
  // The points after the instances: a prune they make due keeps what the graph now holds.
  const InstanceSupport support(s.scene.objects(), config_.semantic.instance_support_margin_m,
                                config_.semantic.instance_support_min_share);
  for (const auto& [detection, lifted] : lifted_detections)
    s.semantic.Add(detection->label, lifted.points, support);
  DropUnsupportedPoints(removed, support);
  s.last_stamp[frame.robot_id] = frame.stamp_ns;

  ++revision_;
  if (++s.accepted_frames == config_.estimate_heights_after_frames) {
    if (std::optional<ClimbingHeights> heights = EstimateHeights(s.columns)) {
      heights->body_m = config_.heights.body_m;  // the robot's, not the map's
      s.grid = HierarchicalGrid(config_.grid, *heights);
      absl::flat_hash_set<VoxelColumns::ColumnId> all;
      for (const auto& [id, column] : s.columns.columns()) all.insert(id);
      s.grid.Update(s.columns, all);
      s.grid_changes.clear();
      s.grid_forgotten_before = revision_;  // every cell may have changed: watchers resync
      result.revision = revision_;
      return result;
    }
  }
  GridWindow changed;
  for (VoxelColumns::ColumnId id : columns) {
    const CellIndex cell = s.grid.CellOf(s.columns.KeyToCoord(VoxelColumns::XKey(id)),
                                         s.columns.KeyToCoord(VoxelColumns::YKey(id)));
    // One cell of margin: eq. 1-2 coverage and the 9x9 / inflation kernels spill into neighbours.
    const int margin = config_.layers.obstacle_kernel / 2 + 1 +
                       static_cast<int>(config_.layers.robot_radius_m / config_.grid.resolution_m);
    changed = Union(changed,
                    GridWindow{{cell.x - margin, cell.y - margin}, 2 * margin + 1, 2 * margin + 1});
  }
  RecordGridChange(changed);
  result.revision = revision_;
  return result;
}

void MappingEngine::DropUnsupportedPoints(const std::vector<SceneObject>& removed,
                                          const InstanceSupport& support) {
  if (removed.empty() || support.supports_all()) return;
  std::set<std::string> labels;
  for (const SceneObject& object : removed) {
    labels.insert(object.label);
    for (const auto& [label, score] : object.label_scores) labels.insert(label);
  }
  state_->semantic.KeepSupported(labels, support);
}

void MappingEngine::RecordGridChange(const GridWindow& changed) {
  State& s = *state_;
  s.grid_changes.push_back({revision_, changed});
  while (s.grid_changes.size() > config_.grid_change_log_size) {
    s.grid_forgotten_before = s.grid_changes.front().first;
    s.grid_changes.pop_front();
  }
}

uint64_t MappingEngine::revision() const {
  absl::ReaderMutexLock lock(&mu_);
  return revision_;
}

GridLayers MappingEngine::Grid(const std::optional<GridWindow>& window, uint64_t* revision,
                               bool with_semantic) const {
  absl::ReaderMutexLock lock(&mu_);
  GridLayers layers =
      RenderLayers(state_->grid, window.value_or(FullWindow(state_->grid)), config_.layers);
  if (with_semantic) state_->semantic.Render(layers);
  if (revision != nullptr) *revision = revision_;
  return layers;
}

std::optional<GridWindow> MappingEngine::GridChangesSince(uint64_t since) const {
  absl::ReaderMutexLock lock(&mu_);
  if (since < state_->grid_forgotten_before) return std::nullopt;
  GridWindow changed;
  for (const auto& [revision, window] : state_->grid_changes) {
    if (revision > since) changed = Union(changed, window);
  }
  return changed;
}

GridWindow MappingEngine::WindowOf(double min_x, double min_y, double max_x, double max_y) const {
  absl::ReaderMutexLock lock(&mu_);
  const CellIndex lo = state_->grid.CellOf(min_x, min_y);
  const CellIndex hi = state_->grid.CellOf(max_x, max_y);
  return {lo, hi.x - lo.x + 1, hi.y - lo.y + 1};
}

std::string MappingEngine::OccupancyBinary(const Eigen::Vector3d& min,
                                           const Eigen::Vector3d& max) const {
  absl::ReaderMutexLock lock(&mu_);
  const octomap::OcTree& tree = *state_->tree;
  octomap::OcTree box(tree.getResolution());
  octomap::OcTreeKey lo;
  octomap::OcTreeKey hi;
  if (tree.coordToKeyChecked(octomap::point3d(min.x(), min.y(), min.z()), lo) &&
      tree.coordToKeyChecked(octomap::point3d(max.x(), max.y(), max.z()), hi)) {
    const unsigned depth = tree.getTreeDepth();
    for (auto it = tree.begin_leafs_bbx(lo, hi); it != tree.end_leafs_bbx(); ++it) {
      // A pruned leaf covers span^3 finest voxels: copy the ones inside the box.
      const int span = 1 << (depth - it.getDepth());
      const octomap::OcTreeKey base = it.getIndexKey();
      for (int dz = 0; dz < span; ++dz) {
        for (int dy = 0; dy < span; ++dy) {
          for (int dx = 0; dx < span; ++dx) {
            const int k[3] = {base[0] + dx, base[1] + dy, base[2] + dz};
            bool inside = true;
            for (int a = 0; a < 3; ++a) inside = inside && k[a] >= lo[a] && k[a] <= hi[a];
            if (!inside) continue;
            box.setNodeValue(octomap::OcTreeKey(static_cast<octomap::key_type>(k[0]),
                                                static_cast<octomap::key_type>(k[1]),
                                                static_cast<octomap::key_type>(k[2])),
                             it->getLogOdds(), /*lazy_eval=*/true);
          }
        }
      }
    }
    box.updateInnerOccupancy();
  }
  std::ostringstream out;
  box.writeBinary(out);
  return out.str();
}

SceneSnapshot MappingEngine::Scene() const {
  absl::ReaderMutexLock lock(&mu_);
  const SceneGraph& g = state_->scene;
  return {g.revision(), g.objects(), g.relations(), g.regions(), g.Summary()};
}

std::optional<SceneDelta> MappingEngine::SceneChangesSince(uint64_t since) const {
  absl::ReaderMutexLock lock(&mu_);
  return state_->scene.ChangesSince(since);
}

namespace {

// Query lists: far above any real query, far below what would cost memory or time.
constexpr size_t kMaxQueryLabels = 256;
constexpr size_t kMaxQueryEmbedding = 4096;

// Every number finite and in range, every list and label within limits, before any lookup.
absl::Status ValidateQuery(const ObjectQuery& query) {
  if (absl::Status s = CheckCount(query.labels.size(), "labels", kMaxQueryLabels); !s.ok()) {
    return s;
  }
  for (size_t i = 0; i < query.labels.size(); ++i) {
    if (absl::Status s = CheckLength(query.labels[i], absl::StrCat("labels[", i, "]"), kMaxIdBytes);
        !s.ok()) {
      return s;
    }
  }
  if (absl::Status s = CheckCount(query.embedding.size(), "embedding", kMaxQueryEmbedding);
      !s.ok()) {
    return s;
  }
  for (size_t i = 0; i < query.embedding.size(); ++i) {
    // As for frames: beyond this a dot product of 4096 components overflows a float.
    if (absl::Status s =
            CheckMagnitude(query.embedding[i], absl::StrCat("embedding[", i, "]"), 1e6);
        !s.ok()) {
      return s;
    }
  }
  if (absl::Status s = CheckRange(query.min_cosine, "min_cosine", -1.0, 1.0); !s.ok()) return s;
  if (query.near.has_value()) {
    const Eigen::Vector3d& near = *query.near;
    if (absl::Status s = CheckPoint(near.x(), near.y(), near.z(), "near", kMaxCoordinateM); !s.ok())
      return s;
  }
  // A radius beyond the world's diameter finds nothing more.
  return CheckRange(query.near_radius_m, "near_radius", 0.0, 2 * kMaxCoordinateM);
}

}  // namespace

absl::StatusOr<std::vector<ObjectHit>> MappingEngine::QueryObjects(const ObjectQuery& query) const {
  if (absl::Status s = ValidateQuery(query); !s.ok()) return s;
  if (query.labels.empty() && query.embedding.empty() && !query.near.has_value()) {
    return InvalidField("labels", "give at least one of labels, embedding or near");
  }
  if (query.near.has_value() && !(query.near_radius_m > 0.0)) {
    return InvalidField("near_radius", "must be > 0 when near is set");
  }
  std::set<std::string> wanted;
  for (const std::string& label : query.labels) {
    const std::string l = Lower(label);
    wanted.insert(l);
    for (const auto& [key, names] : config_.synonyms) {
      const bool listed = std::any_of(names.begin(), names.end(),
                                      [&](const std::string& n) { return Lower(n) == l; });
      if (Lower(key) != l && !listed) continue;
      wanted.insert(Lower(key));
      for (const std::string& n : names) wanted.insert(Lower(n));
    }
  }
  absl::ReaderMutexLock lock(&mu_);
  if (!query.embedding.empty() && state_->embedding_dim != 0 &&
      static_cast<int>(query.embedding.size()) != state_->embedding_dim) {
    return InvalidField("embedding",
                        absl::StrCat("length ", query.embedding.size(), " != map embedding length ",
                                     state_->embedding_dim));
  }
  std::vector<ObjectHit> hits;
  for (const SceneObject& o : state_->scene.objects()) {
    if (!wanted.empty() && !wanted.contains(Lower(o.label))) continue;
    ObjectHit hit{o, 0.0, 0.0};
    if (!query.embedding.empty()) {
      hit.cosine = Cosine(query.embedding, o.embedding);
      if (hit.cosine < query.min_cosine) continue;
    }
    if (query.near.has_value()) {
      hit.distance = (o.position - *query.near).norm();
      if (hit.distance > query.near_radius_m) continue;
    }
    hits.push_back(std::move(hit));
  }
  std::sort(hits.begin(), hits.end(), [](const ObjectHit& a, const ObjectHit& b) {
    if (a.cosine != b.cosine) return a.cosine > b.cosine;
    if (a.object.score != b.object.score) return a.object.score > b.object.score;
    return a.distance < b.distance;
  });
  if (query.max_results > 0 && hits.size() > query.max_results) hits.resize(query.max_results);
  return hits;
}

uint64_t MappingEngine::AwaitChange(uint64_t revision, absl::Duration timeout) const {
  absl::ReaderMutexLock lock(&mu_);  // a reader too: each watch's wake-up excludes no other
  auto changed = [this, revision]()
                     ABSL_SHARED_LOCKS_REQUIRED(mu_) { return revision_ > revision; };
  mu_.AwaitWithTimeout(absl::Condition(&changed), timeout);
  return revision_;
}

std::string MappingEngine::Serialize() const {
  // The tree is written under the lock (readers share it, frames wait ~0.1 s for a fleet's map)
  // and the rest is copied and written outside it: writing the whole map (tens of MB of text in
  // the fleet soak) under the lock held up every frame, grid fetch and query meanwhile, and the
  // live snapshot does it every 5 s. Copying the tree instead allocated and freed its millions
  // of nodes each time, and mapping's RSS followed that peak as the map grew.
  std::string octree;
  std::vector<SceneObject> objects;
  uint64_t next_object_id = 0;
  std::map<std::string, std::vector<Eigen::Vector3f>> points;
  SavedGrid grid;
  grid.resolution_m = config_.grid.resolution_m;
  {
    absl::ReaderMutexLock lock(&mu_);
    const State& s = *state_;
    octree = OctreeSection(*s.tree);
    objects = s.scene.objects();
    next_object_id = s.scene.next_id();
    points = s.semantic.points();
    for (const HierarchicalGrid::CellState& c : s.grid.Cells()) {
      grid.cells.push_back({c.index.x, c.index.y, c.log_odds, c.height, c.structure});
    }
  }
  return SerializeMap(std::move(octree), objects, next_object_id, points, &grid);
}

absl::Status MappingEngine::Restore(const std::string& payload) {
  absl::StatusOr<MapContent> content = ParseMap(payload);
  if (!content.ok()) return content.status();
  if (content->tree->getResolution() != config_.octomap_resolution_m) {
    return FieldStatus(
        absl::StatusCode::kFailedPrecondition, "map_id",
        absl::StrCat("stored octree resolution ", content->tree->getResolution(),
                     " m differs from the configured ", config_.octomap_resolution_m, " m"),
        "FAILED_PRECONDITION");
  }
  absl::MutexLock lock(&mu_);
  state_->Adopt(std::move(*content), config_);
  ++revision_;
  state_->grid_changes.clear();
  state_->grid_forgotten_before = revision_;  // watchers resync with a snapshot
  return absl::OkStatus();
}

absl::StatusOr<ScanMatchResult> MappingEngine::MatchLostScan(
    const std::string& robot_id, const std::optional<PlanarCorrection>& coarse) const {
  if (robot_id.empty()) return InvalidField("robot_id", "must not be empty");
  if (absl::Status s = CheckLength(robot_id, "robot_id", kMaxIdBytes); !s.ok()) return s;
  if (coarse.has_value()) {
    if (absl::Status s = CheckMagnitude(coarse->x, "coarse.x", kMaxCoordinateM); !s.ok()) return s;
    if (absl::Status s = CheckMagnitude(coarse->y, "coarse.y", kMaxCoordinateM); !s.ok()) return s;
    if (absl::Status s = CheckMagnitude(coarse->yaw, "coarse.yaw", 4.0 * M_PI); !s.ok()) return s;
  }
  std::vector<Eigen::Vector2d> scan;
  Eigen::Vector2d robot;
  OccupiedRaster raster;
  {
    absl::ReaderMutexLock lock(&mu_);
    const State& s = *state_;
    const auto found = s.lost_scans.find(robot_id);
    if (found == s.lost_scans.end() || found->second.cells.empty()) {
      return FieldStatus(absl::StatusCode::kNotFound, "robot_id",
                         "the robot sent no untrusted frame with obstacles since it got lost",
                         "NO_LOST_SCAN");
    }
    robot = found->second.robot;
    const double res = s.grid.config().resolution_m;
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e18);
    Eigen::Vector2d hi = Eigen::Vector2d::Constant(-1e18);
    scan.reserve(found->second.cells.size());
    for (const CellIndex& cell : found->second.cells) {
      const Eigen::Vector2d p((cell.x + 0.5) * res, (cell.y + 0.5) * res);
      scan.push_back(p);
      if (coarse.has_value()) {
        const Eigen::Vector2d q = coarse->Apply(p);
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
      }
    }
    // The hash set's order is no order: sort so the answer depends on the cells only.
    std::sort(scan.begin(), scan.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
      return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
    });
    CellIndex min;
    CellIndex max;
    if (coarse.has_value()) {
      // The scan's box after `coarse`, grown by what the search can move a cell: the window plus
      // the rotation of the farthest cell about the centroid.
      const double margin = config_.scan_match.linear_window_m +
                            (hi - lo).norm() * std::sin(config_.scan_match.angular_window_rad) +
                            res;
      min = s.grid.CellOf(lo.x() - margin, lo.y() - margin);
      max = s.grid.CellOf(hi.x() + margin, hi.y() + margin);
    } else if (!s.grid.Bounds(&min, &max)) {
      return FieldStatus(absl::StatusCode::kFailedPrecondition, "robot_id",
                         "the map is empty: nothing to match against", "MAP_EMPTY");
    }
    const GridWindow window{min, max.x - min.x + 1, max.y - min.y + 1};
    const size_t cells = static_cast<size_t>(window.width) * window.height;
    if (!coarse.has_value() && cells > config_.global_scan_match_max_cells) {
      return FieldStatus(absl::StatusCode::kFailedPrecondition, "robot_id",
                         absl::StrCat("the map's ", cells, " cells exceed the global match's ",
                                      config_.global_scan_match_max_cells),
                         "MAP_TOO_LARGE");
    }
    raster = GridRaster(s.grid, window, /*free_and_opaque=*/!coarse.has_value());
    for (const CellIndex& cell : found->second.own_walls) {
      const int x = cell.x - window.min.x;
      const int y = cell.y - window.min.y;
      if (x < 0 || y < 0 || x >= window.width || y >= window.height) continue;
      const size_t at = static_cast<size_t>(y) * window.width + x;
      raster.occupied[at] = 0;
      if (!raster.opaque.empty()) raster.opaque[at] = 0;
    }
  }
  if (coarse.has_value()) return MatchScan(raster, scan, *coarse, config_.scan_match);
  return MatchScanGlobally(raster, scan, robot, config_.scan_match, config_.global_scan_match);
}

void MappingEngine::Reset() {
  MapContent empty;
  empty.tree = std::make_unique<octomap::OcTree>(config_.octomap_resolution_m);
  absl::MutexLock lock(&mu_);
  empty.next_object_id = state_->scene.next_id();
  state_->Adopt(std::move(empty), config_);
  ++revision_;
  state_->grid_changes.clear();
  state_->grid_forgotten_before = revision_;
}

}  // namespace semnav::mapping
