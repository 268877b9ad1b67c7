#include "services/mapping/core/mapping_engine.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <thread>

#include "services/mapping/testing/synthetic_room.h"

namespace semnav::mapping {
namespace {

constexpr int64_t kFrameNs = 100'000'000;  // 10 Hz

// A camera at the room's left end looking down the room.
CameraPose Viewpoint() { return testing::LookAt({0.5, 2.0, 1.2}, {4.0, 2.0, 0.0}); }

// Pixel box around the image projection of map point p (half size in pixels).
PixelBox BoxAround(const Eigen::Vector3d& p, const CameraPose& pose, double half) {
  const Intrinsics k = testing::Vga();
  const Eigen::Vector3d c = pose.orientation.conjugate() * (p - pose.position);
  const double u = k.fx * c.x() / c.z() + k.cx;
  const double v = k.fy * c.y() / c.z() + k.cy;
  return {u - half, v - half, u + half, v + half};
}

uint8_t CellValue(const MappingEngine& engine, double x, double y) {
  const GridWindow window = engine.WindowOf(x, y, x, y);
  return engine.Grid(window, nullptr).hierarchical[0];
}

// The request sweep's valid 4 x 4 frame, 2 m deep, from a camera on voxel corners at (1, 1, 1):
// ray walks met ties at the corner, stepped past the sensor's voxel and out of the scan box, and
// semnav-mapping died with SIGSEGV. A real frame must integrate.
TEST(MappingEngineTest, CameraOnAVoxelCornerIntegrates) {
  MappingEngine engine{MappingConfig{}};
  SensorFrame frame;
  frame.robot_id = "corner";
  frame.stamp_ns = 1'000'000'000;
  frame.intrinsics = {4, 4, 2.0, 2.0, 2.0, 2.0};
  frame.depth.width = 4;
  frame.depth.height = 4;
  frame.depth.encoding = DepthEncoding::kMetres32F;
  const float two_metres = 2.0f;
  for (int i = 0; i < 16; ++i) {
    frame.depth.data.append(reinterpret_cast<const char*>(&two_metres), sizeof(two_metres));
  }
  frame.pose.position = Eigen::Vector3d(1.0, 1.0, 1.0);
  frame.lidar_points.emplace_back(2.0f, 1.0f, 1.0f);
  for (int repeat = 0; repeat < 3; ++repeat) {
    frame.stamp_ns += 100'000'000;
    const absl::StatusOr<FrameResult> result = engine.AddFrame(frame);
    ASSERT_TRUE(result.ok()) << result.status();
  }
  EXPECT_GT(engine.revision(), 0u);
}

TEST(MappingEngineTest, MovingBoxVanishesStaticBoxStays) {
  MappingEngine engine{MappingConfig{}};
  const testing::SyntheticRoom room = testing::StandardRoom();
  const std::vector<double> ys{1.2, 1.6, 2.0, 2.4, 2.8};
  int64_t stamp = 0;
  bool seen_moving_box = false;
  for (double y : ys) {
    testing::SyntheticRoom with_box = room;
    with_box.boxes.push_back({{2.0, y - 0.2, 0.0}, {2.4, y + 0.2, 1.0}});
    for (int repeat = 0; repeat < 2; ++repeat) {
      ASSERT_TRUE(
          engine.AddFrame(testing::RenderFrame(with_box, Viewpoint(), stamp += kFrameNs)).ok());
    }
    const uint8_t value = CellValue(engine, 2.1, y);
    seen_moving_box = seen_moving_box || (value >= 1 && value <= 99);
  }
  EXPECT_TRUE(seen_moving_box);
  for (int i = 0; i < 12; ++i) {
    ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, Viewpoint(), stamp += kFrameNs)).ok());
  }
  for (double y : ys)
    EXPECT_EQ(CellValue(engine, 2.2, y), 0) << "moving box left a trace at y = " << y;
  // Static box: its top face z = 0.8 lies in voxel [0.80, 0.85), centre 0.825 m ->
  // h_o = 100 (0.825 - 0.1) / (2.3 - 0.1) = 33.
  EXPECT_EQ(CellValue(engine, 3.3, 1.3), 33);
  EXPECT_EQ(CellValue(engine, 5.99, 2.0), HierarchicalGrid::kStructure);  // far wall
  EXPECT_EQ(CellValue(engine, 4.5, 2.0), HierarchicalGrid::kFree);
}

TEST(MappingEngineTest, RejectedFramesChangeNothing) {
  MappingEngine engine{MappingConfig{}};
  const testing::SyntheticRoom room = testing::StandardRoom();
  ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, Viewpoint(), 2 * kFrameNs)).ok());
  const uint64_t revision = engine.revision();
  const std::string before = engine.Serialize();

  SensorFrame wrong_size = testing::RenderFrame(room, Viewpoint(), 3 * kFrameNs);
  wrong_size.intrinsics.height = 240;
  EXPECT_EQ(engine.AddFrame(wrong_size).status().code(), absl::StatusCode::kInvalidArgument);
  const SensorFrame backwards = testing::RenderFrame(room, Viewpoint(), 1 * kFrameNs);
  EXPECT_EQ(engine.AddFrame(backwards).status().code(), absl::StatusCode::kFailedPrecondition);
  SensorFrame bad_rgb = testing::RenderFrame(room, Viewpoint(), 3 * kFrameNs);
  bad_rgb.rgb_encoded = "not an image";
  EXPECT_EQ(engine.AddFrame(bad_rgb).status().code(), absl::StatusCode::kInvalidArgument);

  EXPECT_EQ(engine.revision(), revision);
  EXPECT_EQ(engine.Serialize(), before);
  // Another robot has its own clock.
  SensorFrame other = backwards;
  other.robot_id = "robot-2";
  EXPECT_TRUE(engine.AddFrame(other).ok());
}

TEST(MappingEngineTest, DetectionBecomesObjectAndSemanticCells) {
  MappingEngine engine{MappingConfig{}};
  const testing::SyntheticRoom room = testing::StandardRoom();
  for (int i = 0; i < 3; ++i) {
    SensorFrame frame = testing::RenderFrame(room, Viewpoint(), (i + 1) * kFrameNs);
    Detection table;
    table.label = "table";
    table.score = 0.9;
    table.box = BoxAround({3.2, 1.3, 0.7}, Viewpoint(), 40);
    frame.detections.push_back(table);
    const absl::StatusOr<FrameResult> result = engine.AddFrame(frame);
    ASSERT_TRUE(result.ok()) << result.status();
    EXPECT_EQ(result->detections_used, 1u);
  }
  const SceneSnapshot scene = engine.Scene();
  ASSERT_EQ(scene.objects.size(), 1u);
  const SceneObject& object = scene.objects[0];
  EXPECT_EQ(object.detection_count, 3);
  EXPECT_NEAR(object.score, 0.9, 1e-12);
  // The visible front face (x = 3.0) and top (z = 0.8) of the box [3, 3.6] x [1, 1.6] x [0, 0.8].
  EXPECT_NEAR(object.position.x(), 3.05, 0.1);
  EXPECT_NEAR(object.position.y(), 1.3, 0.1);
  EXPECT_GT(object.position.z(), 0.3);
  EXPECT_LT(object.position.z(), 0.85);
  EXPECT_EQ(scene.summary,
            "Scene has 1 objects in 1 regions. Region 0 (area_with_table): 1 table.");

  const GridLayers layers = engine.Grid(engine.WindowOf(2.8, 0.9, 3.7, 1.7), nullptr);
  ASSERT_EQ(layers.semantic_labels, std::vector<std::string>{"table"});
  int labelled = 0;
  for (uint8_t v : layers.semantic) labelled += v == 1 ? 1 : 0;
  EXPECT_GT(labelled, 0);
  // Without the semantic layer (planning's fetch) the other layers are the same.
  const GridLayers plain =
      engine.Grid(engine.WindowOf(2.8, 0.9, 3.7, 1.7), nullptr, /*with_semantic=*/false);
  EXPECT_TRUE(plain.semantic_labels.empty());
  EXPECT_EQ(std::count(plain.semantic.begin(), plain.semantic.end(), uint8_t{1}), 0);
  EXPECT_EQ(plain.occupancy, layers.occupancy);
  EXPECT_EQ(plain.hierarchical, layers.hierarchical);

  const absl::StatusOr<std::vector<ObjectHit>> hits =
      engine.QueryObjects({{"TABLE"}, {}, 0.0, std::nullopt, 0.0, 0});
  ASSERT_TRUE(hits.ok());
  EXPECT_EQ(hits->size(), 1u);
  EXPECT_EQ(engine.QueryObjects({{}, {}, 0.0, std::nullopt, 0.0, 0}).status().code(),
            absl::StatusCode::kInvalidArgument);
}

// A kidnapped robot maps at the pose it wrongly believes; its localizer says so only later
// (mission.md, "Losing the pose"). Frames flagged pose_untrusted mark the instances they touch,
// and the first one also marks what was seen in the lookback window before it, so mapping's
// landmark maps leave them out (before: the look-around's own objects reached the live landmark
// map and relocalization answered the wrong pose back).
TEST(MappingEngineTest, UntrustedFramesAndTheLookbackBeforeThemMarkTheirInstances) {
  MappingConfig config;
  config.scene.untrusted_lookback_s = 2.5;
  MappingEngine engine{config};
  const testing::SyntheticRoom room = testing::StandardRoom();
  auto add = [&](int64_t stamp_ns, const std::string& label, const Eigen::Vector3d& at,
                 bool untrusted) {
    SensorFrame frame = testing::RenderFrame(room, Viewpoint(), stamp_ns);
    frame.pose_untrusted = untrusted;
    if (!label.empty()) {
      Detection detection;
      detection.label = label;
      detection.score = 0.9;
      detection.box = BoxAround(at, Viewpoint(), 30);
      frame.detections.push_back(detection);
    }
    const absl::StatusOr<FrameResult> result = engine.AddFrame(frame);
    ASSERT_TRUE(result.ok()) << result.status();
  };
  const Eigen::Vector3d table(3.2, 1.3, 0.7);
  const Eigen::Vector3d cabinet(5.25, 3.4, 1.2);
  for (int i = 0; i < 3; ++i) add((i + 1) * kFrameNs, "table", table, false);  // t = 0.1-0.3 s
  for (int i = 0; i < 3; ++i) add(50 * kFrameNs + i * kFrameNs, "cabinet", cabinet, false);
  // t = 6 s: the robot reports its loss. The cabinet was last seen at 5.2 s (within 2.5 s), the
  // table at 0.3 s.
  add(60 * kFrameNs, "", Eigen::Vector3d::Zero(), true);
  SceneSnapshot scene = engine.Scene();
  ASSERT_EQ(scene.objects.size(), 2u);
  for (const SceneObject& object : scene.objects) {
    EXPECT_EQ(object.pose_untrusted, object.label == "cabinet") << object.label;
  }
  // A new instance from an untrusted frame is marked; the marks stay once frames are trusted.
  add(61 * kFrameNs, "rug", Eigen::Vector3d(4.0, 2.0, 0.0), true);  // on the floor
  add(62 * kFrameNs, "", Eigen::Vector3d::Zero(), false);
  add(100 * kFrameNs, "table", table, false);
  scene = engine.Scene();
  ASSERT_EQ(scene.objects.size(), 3u);
  for (const SceneObject& object : scene.objects) {
    EXPECT_EQ(object.pose_untrusted, object.label != "table") << object.label;
  }
}

// Camera poses turning in place at `at` (1.2 m high), `count` headings over a full turn.
std::vector<CameraPose> LookAround(const Eigen::Vector2d& at, int count) {
  std::vector<CameraPose> poses;
  for (int i = 0; i < count; ++i) poses.push_back(testing::TurnedAt(at, 2.0 * M_PI * i / count));
  return poses;
}

// A kidnapped robot keeps mapping at the pose it wrongly believes until its localizer reports the
// loss (2.5 s in the simulator). The walls those frames drew lie across the right pose's rays: in
// this room 15 % of them, and the right global match is refused. The robot's match now leaves out
// the cells its own frames turned occupied in the lookback before its first lost frame; walls it
// drew longer before stay (the lookback is the localizer's latency), as the 4 s case shows.
TEST(MappingEngineTest, ALostRobotsMatchLeavesOutTheWallsItDrewInTheLookback) {
  MappingConfig config;
  config.scene.untrusted_lookback_s = 2.5;
  const testing::SyntheticRoom room = testing::StandardRoom();
  const PlanarCorrection wrong{1.0, -0.5, 25.0 * M_PI / 180.0};  // reported = wrong * true
  const Eigen::AngleAxisd turn(wrong.yaw, Eigen::Vector3d::UnitZ());
  auto at_wrong_pose = [&](const CameraPose& pose, int64_t stamp, bool untrusted) {
    SensorFrame frame = testing::RenderFrame(room, pose, stamp);
    const Eigen::Vector2d reported = wrong.Apply(pose.position.head<2>());
    frame.pose.position = Eigen::Vector3d(reported.x(), reported.y(), pose.position.z());
    frame.pose.orientation = Eigen::Quaterniond(turn) * pose.orientation;
    frame.pose_untrusted = untrusted;
    return frame;
  };
  std::map<double, ScanMatchResult> by_report_delay;
  for (const double reported_after_s : {2.0, 4.0}) {
    MappingEngine engine{config};
    int64_t stamp = 0;
    for (const CameraPose& pose : LookAround({3.0, 2.0}, 12)) {
      ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, pose, stamp += kFrameNs)).ok());
    }
    const GridLayers mapped = engine.Grid(std::nullopt, nullptr, false);
    const int64_t kidnapped_at = stamp + 10'000'000'000;  // 10 s later
    stamp = kidnapped_at;
    for (const CameraPose& pose : LookAround({1.5, 2.5}, 8)) {  // trusted, at the wrong pose
      ASSERT_TRUE(engine.AddFrame(at_wrong_pose(pose, stamp += kFrameNs, false)).ok());
    }
    ASSERT_NE(engine.Grid(std::nullopt, nullptr, false).hierarchical, mapped.hierarchical);
    stamp = kidnapped_at + static_cast<int64_t>(reported_after_s * 1e9);
    for (const CameraPose& pose : LookAround({1.5, 2.5}, 8)) {
      ASSERT_TRUE(engine.AddFrame(at_wrong_pose(pose, stamp += kFrameNs, true)).ok());
    }
    absl::StatusOr<ScanMatchResult> global = engine.MatchLostScan("robot-1", std::nullopt);
    ASSERT_TRUE(global.ok()) << global.status();
    by_report_delay[reported_after_s] = *global;
  }
  const PlanarCorrection truth = wrong.Inverse();
  const ScanMatchResult& reported_in_time = by_report_delay[2.0];
  EXPECT_TRUE(reported_in_time.refined);
  EXPECT_LT(std::abs(reported_in_time.correction.yaw - truth.yaw), 1.0 * M_PI / 180.0);
  EXPECT_LT(reported_in_time.ray_conflicts, by_report_delay[4.0].ray_conflicts);
}

// A robot carried off maps nothing while it distrusts its pose: its frames keep their obstacle
// cells for MatchLostScan, which takes relocalization's coarse answer to the walls.
TEST(MappingEngineTest, ALostRobotsFramesStayOutOfTheMapAndRefineItsCorrection) {
  MappingEngine engine{MappingConfig{}};
  const testing::SyntheticRoom room = testing::StandardRoom();
  int64_t stamp = 0;
  for (const CameraPose& pose : LookAround({3.0, 2.0}, 12)) {
    ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, pose, stamp += kFrameNs)).ok());
  }
  const GridLayers before = engine.Grid(std::nullopt, nullptr, false);
  EXPECT_EQ(engine.MatchLostScan("robot-1", {}).status().code(), absl::StatusCode::kNotFound);

  // The robot believes it stands 1 m / -0.5 m and 25 deg from where it is: reported = wrong *
  // true, so the correction that takes its frames to the map is wrong^-1. It reports the loss
  // 10 s after it mapped the room (within the scene's untrusted lookback, the walls it drew would
  // not count for its match: ALostRobotsMatchLeavesOutTheWallsItDrewInTheLookback).
  const PlanarCorrection wrong{1.0, -0.5, 25.0 * M_PI / 180.0};
  const Eigen::AngleAxisd turn(wrong.yaw, Eigen::Vector3d::UnitZ());
  stamp += 10'000'000'000;
  for (const CameraPose& pose : LookAround({1.5, 2.5}, 8)) {
    SensorFrame frame = testing::RenderFrame(room, pose, stamp += kFrameNs);
    const Eigen::Vector2d reported = wrong.Apply(pose.position.head<2>());
    frame.pose.position = Eigen::Vector3d(reported.x(), reported.y(), pose.position.z());
    frame.pose.orientation = Eigen::Quaterniond(turn) * pose.orientation;
    frame.pose_untrusted = true;
    ASSERT_TRUE(engine.AddFrame(frame).ok());
  }
  const GridLayers after = engine.Grid(std::nullopt, nullptr, false);
  EXPECT_EQ(after.hierarchical, before.hierarchical);  // nothing drawn at the wrong pose
  EXPECT_EQ(after.origin_x, before.origin_x);

  const PlanarCorrection truth = wrong.Inverse();
  // Relocalization's answer from a few objects: 0.15 m, -0.1 m and 5 deg off.
  const PlanarCorrection coarse{truth.x + 0.15, truth.y - 0.1, truth.yaw + 5.0 * M_PI / 180.0};
  absl::StatusOr<ScanMatchResult> match = engine.MatchLostScan("robot-1", coarse);
  ASSERT_TRUE(match.ok()) << match.status();
  EXPECT_TRUE(match->refined);
  const Eigen::Vector2d robot_reported = wrong.Apply({1.5, 2.5});
  EXPECT_LT((match->correction.Apply(robot_reported) - Eigen::Vector2d(1.5, 2.5)).norm(), 0.08)
      << match->correction.x << " " << match->correction.y;
  EXPECT_LT(std::abs(match->correction.yaw - truth.yaw), 1.0 * M_PI / 180.0);

  // Without a coarse pose the global search finds the same place: the room's table and cabinet
  // tell its half-turn look-alike apart.
  absl::StatusOr<ScanMatchResult> global = engine.MatchLostScan("robot-1", std::nullopt);
  ASSERT_TRUE(global.ok()) << global.status();
  EXPECT_TRUE(global->refined) << global->score << " vs " << global->runner_up_score;
  EXPECT_LT((global->correction.Apply(robot_reported) - Eigen::Vector2d(1.5, 2.5)).norm(), 0.1);
  EXPECT_LT(std::abs(global->correction.yaw - truth.yaw), 1.0 * M_PI / 180.0);

  // A trusted frame ends the loss: its scan is gone.
  ASSERT_TRUE(
      engine.AddFrame(testing::RenderFrame(room, LookAround({3.0, 2.0}, 1)[0], stamp += kFrameNs))
          .ok());
  EXPECT_EQ(engine.MatchLostScan("robot-1", coarse).status().code(), absl::StatusCode::kNotFound);
}

// A table detected twice, then looked at with the detector running and nothing reported: a
// false detection that recurred. With detector_ran it goes at the 8th miss (8 > 3 x 2); a robot
// without a detector (detector_ran false) says nothing about it, nor does an untrusted pose.
TEST(MappingEngineTest, AnInstanceTheDetectorKeepsNotSeeingGoes) {
  for (const bool detector_ran : {true, false}) {
    for (const bool untrusted : {false, true}) {
      if (!detector_ran && untrusted) continue;
      MappingEngine engine{MappingConfig{}};
      const testing::SyntheticRoom room = testing::StandardRoom();
      int64_t stamp = 0;
      for (int i = 0; i < 2; ++i) {
        SensorFrame frame = testing::RenderFrame(room, Viewpoint(), stamp += kFrameNs);
        frame.detector_ran = true;
        Detection table;
        table.label = "table";
        table.score = 0.9;
        table.box = BoxAround({3.2, 1.3, 0.7}, Viewpoint(), 40);
        frame.detections.push_back(table);
        ASSERT_TRUE(engine.AddFrame(frame).ok());
      }
      ASSERT_EQ(engine.Scene().objects.size(), 1u);
      for (int miss = 1; miss <= 8; ++miss) {
        SensorFrame frame = testing::RenderFrame(room, Viewpoint(), stamp += kFrameNs);
        frame.detector_ran = detector_ran;
        frame.pose_untrusted = untrusted;
        ASSERT_TRUE(engine.AddFrame(frame).ok());
        const SceneSnapshot scene = engine.Scene();
        const bool counted = detector_ran && !untrusted;
        if (counted && miss == 8) {
          EXPECT_TRUE(scene.objects.empty());
        } else {
          ASSERT_EQ(scene.objects.size(), 1u) << "miss " << miss;
          EXPECT_EQ(scene.objects[0].misses, counted ? miss : 0);
        }
      }
    }
  }
}

// The semantic points of an instance the scene graph removed go with it (fleet bench: every
// false detection's patch stayed, and mapping's RSS kept growing after the scene graph settled);
// with instance_support_margin_m < 0 they stay.
TEST(MappingEngineTest, ARemovedInstanceTakesItsSemanticPointsAlong) {
  for (const double margin : {0.25, -1.0}) {
    MappingConfig config;
    config.semantic.instance_support_margin_m = margin;
    MappingEngine engine{config};
    const testing::SyntheticRoom room = testing::StandardRoom();
    int64_t stamp = 0;
    auto frame_with = [&](std::vector<Detection> detections) {
      SensorFrame frame = testing::RenderFrame(room, Viewpoint(), stamp += kFrameNs);
      frame.detector_ran = true;
      frame.detections = std::move(detections);
      return frame;
    };
    Detection table;
    table.label = "table";
    table.score = 0.9;
    table.box = BoxAround({3.2, 1.3, 0.7}, Viewpoint(), 40);
    for (int i = 0; i < 2; ++i) ASSERT_TRUE(engine.AddFrame(frame_with({table})).ok());
    const GridWindow window = engine.WindowOf(2.8, 0.9, 3.7, 1.7);
    ASSERT_EQ(engine.Grid(window, nullptr).semantic_labels, std::vector<std::string>{"table"});
    for (int miss = 1; miss <= 8; ++miss) ASSERT_TRUE(engine.AddFrame(frame_with({})).ok());
    ASSERT_TRUE(engine.Scene().objects.empty());
    const GridLayers layers = engine.Grid(window, nullptr);
    if (margin >= 0.0) {
      EXPECT_TRUE(layers.semantic_labels.empty());
      EXPECT_EQ(std::count(layers.semantic.begin(), layers.semantic.end(), uint8_t{1}), 0);
    } else {
      EXPECT_EQ(layers.semantic_labels, std::vector<std::string>{"table"});
    }
  }
}

TEST(MappingEngineTest, BlurredColourImageSkipsDetectionsButKeepsDepth) {
  MappingEngine engine{MappingConfig{}};
  SensorFrame frame = testing::RenderFrame(testing::StandardRoom(), Viewpoint(), kFrameNs);
  std::vector<uchar> png;
  cv::imencode(".png", cv::Mat(480, 640, CV_8U, cv::Scalar(128)),
               png);  // flat: Laplacian variance 0
  frame.rgb_encoded.assign(png.begin(), png.end());
  Detection det;
  det.label = "table";
  det.score = 0.9;
  det.box = BoxAround({3.2, 1.3, 0.7}, Viewpoint(), 40);
  frame.detections.push_back(det);
  const absl::StatusOr<FrameResult> result = engine.AddFrame(frame);
  ASSERT_TRUE(result.ok());
  EXPECT_TRUE(result->blurred);
  EXPECT_EQ(result->detections_used, 0u);
  EXPECT_GT(result->voxels_updated, 100000u);
  EXPECT_TRUE(engine.Scene().objects.empty());
}

TEST(MappingEngineTest, LidarPointsAreIntegrated) {
  MappingEngine engine{MappingConfig{}};
  SensorFrame frame = testing::RenderFrame(testing::StandardRoom(), Viewpoint(), kFrameNs);
  std::fill(frame.depth.data.begin(), frame.depth.data.end(), '\0');  // no depth at all
  frame.lidar_points = {Eigen::Vector3f(0.0f, 0.0f, 2.0f),
                        Eigen::Vector3f(0.0f, 0.0f, 20.0f)};  // 2nd beyond 8 m
  const absl::StatusOr<FrameResult> result = engine.AddFrame(frame);
  ASSERT_TRUE(result.ok());
  // 2 m along the optical axis at 0.05 m: the hit voxel plus the ~40 voxels the ray passes.
  EXPECT_GE(result->voxels_updated, 40u);
  EXPECT_LE(result->voxels_updated, 60u);
}

TEST(MappingEngineTest, QueriesBySynonymEmbeddingAndDistance) {
  MappingConfig config;
  config.synonyms["sofa"] = {"couch"};
  MappingEngine engine{config};
  SensorFrame frame = testing::RenderFrame(testing::StandardRoom(), Viewpoint(), kFrameNs);
  Detection det;
  det.label = "sofa";
  det.score = 0.8;
  det.box = BoxAround({3.2, 1.3, 0.7}, Viewpoint(), 40);
  det.embedding = {0.0f, 1.0f};
  frame.detections.push_back(det);
  ASSERT_TRUE(engine.AddFrame(frame).ok());

  ObjectQuery by_synonym;
  by_synonym.labels = {"Couch"};
  EXPECT_EQ(engine.QueryObjects(by_synonym)->size(), 1u);
  ObjectQuery by_embedding;
  by_embedding.embedding = {0.0f, 2.0f};
  by_embedding.min_cosine = 0.9;
  ASSERT_EQ(engine.QueryObjects(by_embedding)->size(), 1u);
  EXPECT_NEAR(engine.QueryObjects(by_embedding)->front().cosine, 1.0, 1e-6);
  by_embedding.embedding = {1.0f, 0.0f};  // orthogonal: cosine 0 < 0.9
  EXPECT_TRUE(engine.QueryObjects(by_embedding)->empty());
  by_embedding.embedding = {1.0f, 0.0f, 0.0f};
  EXPECT_EQ(engine.QueryObjects(by_embedding).status().code(), absl::StatusCode::kInvalidArgument);
  ObjectQuery far;
  far.near = Eigen::Vector3d(0.0, 0.0, 0.0);
  far.near_radius_m = 1.0;
  EXPECT_TRUE(engine.QueryObjects(far)->empty());
  far.near_radius_m = 0.0;
  EXPECT_EQ(engine.QueryObjects(far).status().code(), absl::StatusCode::kInvalidArgument);
}

TEST(MappingEngineTest, EstimatesFootAndCeilingFromTheMapAtStartUp) {
  MappingConfig config;
  config.estimate_heights_after_frames = 2;
  MappingEngine engine{config};
  const testing::SyntheticRoom room = testing::StandardRoom();
  const CameraPose level =
      testing::LookAt({0.5, 2.0, 1.2}, {6.0, 2.0, 1.2});  // sees floor and ceiling
  ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, level, kFrameNs)).ok());
  EXPECT_EQ(engine.Grid(GridWindow{{0, 0}, 1, 1}, nullptr).heights.ceiling_m,
            2.3);  // configured until then
  ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, level, 2 * kFrameNs)).ok());
  const ClimbingHeights heights = engine.Grid(GridWindow{{0, 0}, 1, 1}, nullptr).heights;
  // Floor z = 0 -> voxel [0, 0.05), h_f one voxel up: 0.075; ceiling z = 2.5 -> voxel
  // [2.5, 2.55), h_c one voxel down: 2.475.
  EXPECT_NEAR(heights.foot_m, 0.075, 1e-9);
  EXPECT_NEAR(heights.ceiling_m, 2.475, 1e-9);
  EXPECT_EQ(CellValue(engine, 6.02, 2.0),
            HierarchicalGrid::kStructure);               // behind the far wall's face
  EXPECT_FALSE(engine.GridChangesSince(1).has_value());  // watchers must resync
}

// Readers share the engine's lock (grid fetches, scene reads, snapshots) while frames change the
// map: every reader sees revisions in order, and reading changes nothing: the map afterwards is
// the map of the same frames fed with no reader at all.
TEST(MappingEngineTest, ReadersRunBesideFramesAndChangeNothing) {
  const testing::SyntheticRoom room = testing::StandardRoom();
  auto frame = [&](int i) {
    const CameraPose pose = testing::LookAt({0.5, 1.5 + 0.1 * (i % 10), 1.2}, {4.0, 2.0, 0.0});
    SensorFrame f = testing::RenderFrame(room, pose, (i + 1) * kFrameNs);
    Detection table;
    table.label = "table";
    table.score = 0.9;
    table.box = BoxAround({3.2, 1.3, 0.7}, pose, 40);
    f.detections.push_back(table);
    return f;
  };
  constexpr int kFrames = 12;
  MappingEngine alone{MappingConfig{}};
  for (int i = 0; i < kFrames; ++i) ASSERT_TRUE(alone.AddFrame(frame(i)).ok());

  MappingEngine shared{MappingConfig{}};
  std::atomic<bool> writing{true};
  std::vector<std::thread> readers;
  std::atomic<int> out_of_order{0};
  for (int r = 0; r < 3; ++r) {
    readers.emplace_back([&, r] {
      uint64_t last = 0;
      while (writing) {
        uint64_t revision = 0;
        (void)shared.Grid(std::nullopt, &revision, /*with_semantic=*/r == 0);
        if (revision < last) ++out_of_order;
        last = revision;
        if (r == 1) (void)shared.Serialize();
        if (r == 2) (void)shared.Scene();
      }
    });
  }
  for (int i = 0; i < kFrames; ++i) ASSERT_TRUE(shared.AddFrame(frame(i)).ok());
  writing = false;
  for (std::thread& reader : readers) reader.join();

  EXPECT_EQ(out_of_order, 0);
  EXPECT_EQ(shared.revision(), alone.revision());
  EXPECT_EQ(shared.Serialize(), alone.Serialize());
  const GridLayers a = alone.Grid(std::nullopt, nullptr, true);
  const GridLayers b = shared.Grid(std::nullopt, nullptr, true);
  EXPECT_EQ(a.hierarchical, b.hierarchical);
  EXPECT_EQ(a.semantic, b.semantic);
}

TEST(MappingEngineTest, RestoreRoundTripsAndRejectsGarbageUntouched) {
  MappingConfig config;
  MappingEngine engine{config};
  const testing::SyntheticRoom room = testing::StandardRoom();
  ASSERT_TRUE(engine.AddFrame(testing::RenderFrame(room, Viewpoint(), kFrameNs)).ok());
  const std::string saved = engine.Serialize();

  MappingEngine copy{config};
  ASSERT_TRUE(copy.Restore(saved).ok());
  EXPECT_EQ(CellValue(copy, 3.3, 1.3), CellValue(engine, 3.3, 1.3));
  EXPECT_EQ(copy.Serialize(), saved);

  const uint64_t revision = copy.revision();
  EXPECT_EQ(copy.Restore(saved.substr(0, saved.size() / 2)).code(), absl::StatusCode::kDataLoss);
  EXPECT_EQ(copy.revision(), revision);
  EXPECT_EQ(copy.Serialize(), saved);
}

}  // namespace
}  // namespace semnav::mapping
