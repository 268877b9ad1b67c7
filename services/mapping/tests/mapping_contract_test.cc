// Contract test: the real semnav-mapping binary on a loopback port, called through generated stubs.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <signal.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "absl/time/clock.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/mapping/testing/frame_proto.h"
#include "services/mapping/testing/synthetic_room.h"
#include "tests/support/service_process.h"

namespace semnav::mapping {
namespace {

using semnav::common::v1::ErrorInfo;
using ::testing::HasSubstr;

constexpr int64_t kFrameNs = 100'000'000;

// A room frame with a "table" detection around the static box, optionally with an embedding.
v1::SensorFrame RoomFrame(int64_t stamp, const std::vector<float>& embedding = {}) {
  return testing::StandardRoomFrameWithTable(stamp, embedding);
}

class MappingContractTest : public ::testing::Test {
 protected:
  void SetUp() override {
    store_ = ::testing::TempDir() + "/mapping_contract_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::remove_all(store_);
    const std::string config = store_ + ".yaml";
    std::ofstream(config) << "mapping:\n  store_directory: " << store_
                          << "\n  watch_min_interval_ms: 50\n";
    absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> process =
        semnav::testing::ServiceProcess::Start("semnav-mapping", {"--config", config});
    ASSERT_TRUE(process.ok()) << process.status();
    process_ = *std::move(process);
    stub_ = v1::MappingService::NewStub(process_->channel());
  }

  // Streams frames and returns their acks.
  std::vector<v1::FrameAck> Stream(const std::vector<v1::SensorFrame>& frames) {
    grpc::ClientContext context;
    auto stream = stub_->StreamFrames(&context);
    std::vector<v1::FrameAck> acks;
    for (const v1::SensorFrame& frame : frames) {
      v1::StreamFramesRequest request;
      *request.mutable_frame() = frame;
      EXPECT_TRUE(stream->Write(request));
      v1::StreamFramesResponse response;
      EXPECT_TRUE(stream->Read(&response));
      acks.push_back(response.ack());
    }
    stream->WritesDone();
    EXPECT_TRUE(stream->Finish().ok());
    return acks;
  }

  v1::GetGridMapResponse Grid() {
    grpc::ClientContext context;
    v1::GetGridMapRequest request;
    v1::GetGridMapResponse response;
    EXPECT_TRUE(stub_->GetGridMap(&context, request, &response).ok());
    return response;
  }

  v1::SceneGraph Scene() {
    grpc::ClientContext context;
    v1::GetSceneGraphResponse response;
    EXPECT_TRUE(stub_->GetSceneGraph(&context, v1::GetSceneGraphRequest(), &response).ok());
    return response.graph();
  }

  std::string store_;
  std::unique_ptr<semnav::testing::ServiceProcess> process_;
  std::unique_ptr<v1::MappingService::Stub> stub_;
};

uint8_t CellAt(const semnav::common::v1::GridMap& grid, double x, double y) {
  const int col = static_cast<int>(std::floor((x - grid.origin().x()) / grid.resolution()));
  const int row = static_cast<int>(std::floor((y - grid.origin().y()) / grid.resolution()));
  for (const auto& layer : grid.layers()) {
    if (layer.kind() == semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL) {
      return static_cast<uint8_t>(layer.data()[static_cast<size_t>(row) * grid.width() + col]);
    }
  }
  return 0;
}

TEST_F(MappingContractTest, SyntheticRoomFramesBecomeGridAndSceneGraph) {
  const std::vector<v1::FrameAck> acks =
      Stream({RoomFrame(kFrameNs), RoomFrame(2 * kFrameNs), RoomFrame(3 * kFrameNs)});
  for (size_t i = 0; i < acks.size(); ++i) {
    EXPECT_TRUE(acks[i].accepted()) << acks[i].error().ShortDebugString();
    EXPECT_EQ(acks[i].sequence(), i);
    EXPECT_EQ(acks[i].revision(), i + 1);
    EXPECT_EQ(acks[i].detections_used(), 1u);
  }
  const semnav::common::v1::GridMap grid = Grid().grid();
  EXPECT_EQ(grid.resolution(), 0.05);
  EXPECT_EQ(grid.revision(), 3u);
  EXPECT_EQ(grid.layers_size(), 6);
  EXPECT_EQ(grid.semantic_labels(0), "table");
  EXPECT_EQ(CellAt(grid, 3.3, 1.3), 33);    // static box: h_o of its 0.825 m top voxel
  EXPECT_EQ(CellAt(grid, 5.99, 2.0), 100);  // far wall: structure
  EXPECT_EQ(CellAt(grid, 4.5, 2.0), 0);     // free floor

  const v1::SceneGraph scene = Scene();
  ASSERT_EQ(scene.objects_size(), 1);
  EXPECT_EQ(scene.objects(0).label(), "table");
  EXPECT_EQ(scene.objects(0).observation_count(), 3u);
  EXPECT_NEAR(scene.objects(0).position().y(), 1.3, 0.1);
  EXPECT_EQ(scene.summary(),
            "Scene has 1 objects in 1 regions. Region 0 (area_with_table): 1 table.");
}

TEST_F(MappingContractTest, BadFramesAreRejectedWithTheirFieldAndChangeNothing) {
  const std::vector<float> embedding{1.0f, 0.0f, 0.0f};
  std::vector<v1::SensorFrame> frames{RoomFrame(10 * kFrameNs, embedding)};
  std::vector<std::string> fields;
  auto bad = [&](const std::string& field, auto mutate) {
    v1::SensorFrame frame = RoomFrame(11 * kFrameNs, embedding);
    mutate(frame);
    frames.push_back(frame);
    fields.push_back(field);
  };
  bad("depth.width", [](v1::SensorFrame& f) { f.mutable_intrinsics()->set_width(320); });
  bad("depth.encoding", [](v1::SensorFrame& f) {
    f.mutable_depth()->set_encoding(semnav::common::v1::IMAGE_ENCODING_MONO8);
  });
  bad("pose.orientation",
      [](v1::SensorFrame& f) { f.mutable_camera_pose()->mutable_orientation()->set_w(0.5); });
  bad("pose.position.x",
      [](v1::SensorFrame& f) { f.mutable_camera_pose()->mutable_position()->set_x(std::nan("")); });
  bad("stamp", [](v1::SensorFrame& f) { f.mutable_header()->mutable_stamp()->set_seconds(0); });
  bad("detections[0].box",
      [](v1::SensorFrame& f) { f.mutable_detections(0)->mutable_box()->set_x_max(700); });
  bad("detections[0].embedding",
      [](v1::SensorFrame& f) { f.mutable_detections(0)->add_embedding(0.5f); });
  frames.push_back(RoomFrame(12 * kFrameNs, embedding));  // the stream goes on

  const std::vector<v1::FrameAck> acks = Stream(frames);
  ASSERT_EQ(acks.size(), frames.size());
  EXPECT_TRUE(acks.front().accepted());
  for (size_t i = 0; i < fields.size(); ++i) {
    const v1::FrameAck& ack = acks[i + 1];
    EXPECT_FALSE(ack.accepted()) << fields[i];
    EXPECT_EQ(ack.error().field(), fields[i]);
    EXPECT_EQ(ack.error().reason(),
              fields[i] == "stamp" ? "FAILED_PRECONDITION" : "INVALID_ARGUMENT");
    EXPECT_EQ(ack.revision(), 1u) << fields[i];  // unchanged
  }
  EXPECT_TRUE(acks.back().accepted());
  EXPECT_EQ(acks.back().revision(), 2u);
  const v1::SceneGraph scene = Scene();
  ASSERT_EQ(scene.objects_size(), 1);
  EXPECT_EQ(scene.objects(0).observation_count(), 2u);  // only the two good frames
}

TEST_F(MappingContractTest, BadRequestsNameTheFieldAndKeepState) {
  Stream({RoomFrame(kFrameNs)});
  const std::string before = Grid().SerializeAsString();
  {
    grpc::ClientContext context;
    v1::GetGridMapRequest request;
    request.mutable_window()->mutable_min()->set_x(2.0);
    request.mutable_window()->mutable_max()->set_x(1.0);
    request.mutable_window()->mutable_max()->set_y(1.0);
    v1::GetGridMapResponse response;
    const grpc::Status status = stub_->GetGridMap(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "window.max.x");
  }
  {
    grpc::ClientContext context;
    v1::QueryObjectsResponse response;
    const grpc::Status status = stub_->QueryObjects(&context, v1::QueryObjectsRequest(), &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "labels");
  }
  {
    grpc::ClientContext context;
    v1::SaveMapRequest request;
    request.set_map_id("lab");
    v1::SaveMapResponse response;
    const grpc::Status status = stub_->SaveMap(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "request_id");
  }
  {
    grpc::ClientContext context;
    v1::LoadMapRequest request;
    request.set_request_id("load-1");
    request.set_map_id("../etc");
    v1::LoadMapResponse response;
    const grpc::Status status = stub_->LoadMap(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "map_id");
  }
  {
    grpc::ClientContext context;
    v1::GetOccupancyRequest request;
    request.mutable_max()->set_x(1.0);
    request.mutable_max()->set_y(1.0);
    auto reader = stub_->GetOccupancy(&context, request);
    v1::GetOccupancyResponse chunk;
    EXPECT_FALSE(reader->Read(&chunk));
    const grpc::Status status = reader->Finish();
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "max.z");
  }
  EXPECT_EQ(Grid().SerializeAsString(), before);
}

// Regression: on an empty map, WatchGridMap without since_revision and a window edge at +-inf
// or 1e300 aborted the process (std::length_error), and GetGridMap with max.x = 1e6 grew it to
// 6 GB. Each is now INVALID_ARGUMENT naming the field, and the service keeps serving.
TEST_F(MappingContractTest, UnboundedWindowsAreRejectedAndTheServiceSurvives) {
  const double inf = std::numeric_limits<double>::infinity();
  const struct {
    double min_x, max_x, max_y;
    const char* field;
  } cases[] = {{0.0, inf, 1.0, "window.max.x"},   {-inf, 1.0, 1.0, "window.min.x"},
               {0.0, 1e300, 1.0, "window.max.x"}, {0.0, std::nan(""), 1.0, "window.max.x"},
               {0.0, 1e6, 1.0, "window.max.x"},   {-5000.0, 5000.0, 5000.0, "window"}};
  for (const auto& c : cases) {
    v1::Window window;
    window.mutable_min()->set_x(c.min_x);
    window.mutable_max()->set_x(c.max_x);
    window.mutable_max()->set_y(c.max_y);
    {
      grpc::ClientContext context;
      context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(5));
      v1::WatchGridMapRequest request;
      *request.mutable_window() = window;
      auto reader = stub_->WatchGridMap(&context, request);
      v1::WatchGridMapResponse response;
      EXPECT_FALSE(reader->Read(&response));
      const grpc::Status status = reader->Finish();
      EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
          << c.field << " " << status.error_message();
      ASSERT_TRUE(GetDetail<ErrorInfo>(status).has_value()) << c.field;
      EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), c.field);
      EXPECT_LT(status.error_message().size(), 200u);
    }
    {
      grpc::ClientContext context;
      context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(5));
      v1::GetGridMapRequest request;
      *request.mutable_window() = window;
      v1::GetGridMapResponse response;
      const grpc::Status status = stub_->GetGridMap(&context, request, &response);
      EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << c.field;
      EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), c.field);
    }
  }
  // Still alive and answering.
  EXPECT_EQ(Grid().grid().width(), 0);
}

// A mapping service that dies (SIGKILL, as an OOM kill or a crash) and is started again keeps its
// live map: the snapshot in <store>/live brings back every cell and object. A clean stop
// (SIGTERM) discards it, so a fresh start begins empty.
TEST_F(MappingContractTest, LiveMapSurvivesACrashButNotACleanStop) {
  const std::string config = store_ + "-live.yaml";
  std::ofstream(config) << "mapping:\n  store_directory: " << store_
                        << "\n  live_snapshot_interval_s: 0.1\n";
  auto start = [&] {
    absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> process =
        semnav::testing::ServiceProcess::Start("semnav-mapping", {"--config", config});
    EXPECT_TRUE(process.ok()) << process.status();
    return process.ok() ? *std::move(process) : nullptr;
  };
  process_ = start();
  ASSERT_NE(process_, nullptr);
  stub_ = v1::MappingService::NewStub(process_->channel());
  Stream({RoomFrame(kFrameNs), RoomFrame(2 * kFrameNs)});
  const v1::GetGridMapResponse before = Grid();
  ASSERT_GT(before.grid().width(), 0);
  const int objects = Scene().objects_size();
  ASSERT_EQ(objects, 1);
  absl::SleepFor(absl::Milliseconds(500));  // a few snapshot periods

  ::kill(process_->pid(), SIGKILL);
  process_.reset();
  process_ = start();
  ASSERT_NE(process_, nullptr);
  stub_ = v1::MappingService::NewStub(process_->channel());
  const v1::GetGridMapResponse after = Grid();
  EXPECT_EQ(after.grid().width(), before.grid().width());
  EXPECT_EQ(after.grid().height(), before.grid().height());
  ASSERT_EQ(after.grid().layers_size(), before.grid().layers_size());
  for (int i = 0; i < before.grid().layers_size(); ++i) {
    EXPECT_EQ(after.grid().layers(i).data(), before.grid().layers(i).data()) << "layer " << i;
  }
  EXPECT_EQ(Scene().objects_size(), objects);

  ASSERT_TRUE(process_->Terminate().ok());
  process_ = start();
  ASSERT_NE(process_, nullptr);
  stub_ = v1::MappingService::NewStub(process_->channel());
  EXPECT_EQ(Grid().grid().width(), 0);
  EXPECT_EQ(Scene().objects_size(), 0);
}

TEST_F(MappingContractTest, SaveLoadAndCorruptFileIsDataLossWithLiveMapUntouched) {
  Stream({RoomFrame(kFrameNs)});
  v1::SaveMapRequest save;
  save.set_request_id("save-1");
  save.set_map_id("lab");
  v1::SaveMapResponse saved;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(stub_->SaveMap(&context, save, &saved).ok());
    EXPECT_EQ(saved.map().map_id(), "lab");
    EXPECT_GT(saved.map().size_bytes(), 1000u);
  }
  Stream({RoomFrame(2 * kFrameNs)});
  {
    // Same request_id: the first answer, no second save.
    grpc::ClientContext context;
    v1::SaveMapResponse again;
    ASSERT_TRUE(stub_->SaveMap(&context, save, &again).ok());
    EXPECT_EQ(again.SerializeAsString(), saved.SerializeAsString());
  }
  {
    grpc::ClientContext context;
    v1::ResetMapRequest reset;
    reset.set_request_id("reset-1");
    v1::ResetMapResponse response;
    ASSERT_TRUE(stub_->ResetMap(&context, reset, &response).ok());
    EXPECT_EQ(Scene().objects_size(), 0);
  }
  {
    grpc::ClientContext context;
    v1::LoadMapRequest load;
    load.set_request_id("load-1");
    load.set_map_id("lab");
    v1::LoadMapResponse response;
    ASSERT_TRUE(stub_->LoadMap(&context, load, &response).ok());
    ASSERT_EQ(Scene().objects_size(), 1);
    EXPECT_EQ(Scene().objects(0).observation_count(), 1u);  // the state when saved
    EXPECT_EQ(CellAt(Grid().grid(), 3.3, 1.3), 33);
  }
  {
    std::fstream file(store_ + "/lab.snmap", std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(100);
    file.put('\x7f');
  }
  const std::string grid_before = Grid().SerializeAsString();
  const std::string scene_before = Scene().SerializeAsString();
  {
    grpc::ClientContext context;
    v1::LoadMapRequest load;
    load.set_request_id("load-2");
    load.set_map_id("lab");
    v1::LoadMapResponse response;
    const grpc::Status status = stub_->LoadMap(&context, load, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::DATA_LOSS);
    EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "map_id");
  }
  EXPECT_EQ(Grid().SerializeAsString(), grid_before);
  EXPECT_EQ(Scene().SerializeAsString(), scene_before);
  {
    grpc::ClientContext context;
    v1::ListMapsResponse list;
    ASSERT_TRUE(stub_->ListMaps(&context, v1::ListMapsRequest(), &list).ok());
    ASSERT_EQ(list.maps_size(), 1);
    EXPECT_EQ(list.maps(0).map_id(), "lab");
  }
}

TEST_F(MappingContractTest, OccupancyComesBackAsOctomapChunks) {
  Stream({RoomFrame(kFrameNs)});
  grpc::ClientContext context;
  v1::GetOccupancyRequest request;
  request.mutable_min()->set_z(-0.1);
  request.mutable_max()->set_x(6.1);
  request.mutable_max()->set_y(4.1);
  request.mutable_max()->set_z(2.6);
  auto reader = stub_->GetOccupancy(&context, request);
  std::string payload;
  v1::GetOccupancyResponse response;
  std::string sha256;
  std::string content_type;
  while (reader->Read(&response)) {
    EXPECT_EQ(response.chunk().offset(), payload.size());
    payload += response.chunk().data();
    if (!response.chunk().sha256().empty()) sha256 = response.chunk().sha256();
    if (!response.chunk().content_type().empty()) content_type = response.chunk().content_type();
  }
  ASSERT_TRUE(reader->Finish().ok());
  EXPECT_EQ(content_type, "application/x-octomap-bt");
  EXPECT_EQ(sha256.size(), 64u);
  octomap::OcTree tree(0.05);
  std::istringstream in(payload);
  ASSERT_TRUE(tree.readBinary(in));
  const octomap::OcTreeNode* wall = tree.search(5.99, 2.0, 1.0);
  ASSERT_NE(wall, nullptr);
  EXPECT_TRUE(tree.isNodeOccupied(wall));
}

TEST_F(MappingContractTest, SceneWatchSendsSnapshotThenDelta) {
  grpc::ClientContext context;
  v1::WatchSceneGraphRequest request;
  auto reader = stub_->WatchSceneGraph(&context, request);
  v1::WatchSceneGraphResponse first;
  ASSERT_TRUE(reader->Read(&first));
  ASSERT_TRUE(first.has_snapshot());
  EXPECT_EQ(first.snapshot().objects_size(), 0);
  Stream({RoomFrame(kFrameNs)});
  v1::WatchSceneGraphResponse second;
  ASSERT_TRUE(reader->Read(&second));
  ASSERT_TRUE(second.has_delta());
  EXPECT_EQ(second.delta().from_revision(), first.snapshot().revision());
  ASSERT_EQ(second.delta().upserted_objects_size(), 1);
  EXPECT_EQ(second.delta().upserted_objects(0).label(), "table");
  context.TryCancel();
}

// detector_ran over the wire: frames that show the table without detecting it remove it after 8
// misses (2 detections), and a watcher hears of the removal; without the flag they change nothing.
TEST_F(MappingContractTest, AnObjectTheDetectorKeepsMissingIsRemoved) {
  std::vector<v1::SensorFrame> frames = {RoomFrame(kFrameNs), RoomFrame(2 * kFrameNs)};
  for (int i = 0; i < 8; ++i) {  // no detector: no evidence
    v1::SensorFrame blind = RoomFrame((3 + i) * kFrameNs);
    blind.clear_detections();
    frames.push_back(blind);
  }
  for (const v1::FrameAck& ack : Stream(frames)) EXPECT_TRUE(ack.accepted());
  ASSERT_EQ(Scene().objects_size(), 1);

  grpc::ClientContext context;
  v1::WatchSceneGraphRequest request;
  auto reader = stub_->WatchSceneGraph(&context, request);
  v1::WatchSceneGraphResponse snapshot;
  ASSERT_TRUE(reader->Read(&snapshot));
  ASSERT_EQ(snapshot.snapshot().objects_size(), 1);
  const uint64_t table = snapshot.snapshot().objects(0).id();
  frames.clear();
  for (int i = 0; i < 8; ++i) {
    v1::SensorFrame looked = RoomFrame((11 + i) * kFrameNs);
    looked.clear_detections();
    looked.set_detector_ran(true);
    frames.push_back(looked);
  }
  for (const v1::FrameAck& ack : Stream(frames)) EXPECT_TRUE(ack.accepted());
  EXPECT_EQ(Scene().objects_size(), 0);
  v1::WatchSceneGraphResponse removal;
  ASSERT_TRUE(reader->Read(&removal));
  ASSERT_TRUE(removal.has_delta());
  ASSERT_EQ(removal.delta().removed_object_ids_size(), 1);
  EXPECT_EQ(removal.delta().removed_object_ids(0), table);
  context.TryCancel();
}

TEST_F(MappingContractTest, GridWatchSendsSnapshotThenChangedWindowAndResumes) {
  Stream({RoomFrame(kFrameNs)});
  uint64_t resume_from = 0;
  {
    grpc::ClientContext context;
    v1::WatchGridMapRequest request;
    request.add_layers(semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
    auto reader = stub_->WatchGridMap(&context, request);
    v1::WatchGridMapResponse first;
    ASSERT_TRUE(reader->Read(&first));
    EXPECT_TRUE(first.snapshot());
    EXPECT_EQ(first.grid().revision(), 1u);
    EXPECT_EQ(first.grid().layers_size(), 1);
    Stream({RoomFrame(2 * kFrameNs)});
    v1::WatchGridMapResponse second;
    ASSERT_TRUE(reader->Read(&second));
    EXPECT_FALSE(second.snapshot());
    EXPECT_EQ(second.grid().revision(), 2u);
    EXPECT_GT(second.grid().width(), 0u);
    EXPECT_EQ(CellAt(second.grid(), 3.3, 1.3), 33);
    resume_from = second.grid().revision();
    context.TryCancel();
  }
  Stream({RoomFrame(3 * kFrameNs)});
  grpc::ClientContext context;
  v1::WatchGridMapRequest request;
  request.set_since_revision(resume_from);
  auto reader = stub_->WatchGridMap(&context, request);
  v1::WatchGridMapResponse resumed;
  ASSERT_TRUE(reader->Read(&resumed));
  EXPECT_FALSE(resumed.snapshot());  // only what changed after revision 2
  EXPECT_EQ(resumed.grid().revision(), 3u);
  context.TryCancel();
}

}  // namespace
}  // namespace semnav::mapping

namespace semnav::mapping {
namespace {

// A robot that reports a wrong pose streams its look-around with pose_untrusted: nothing of it
// enters the grid, and MatchLostScan takes a coarse correction to the walls it saw.
TEST_F(MappingContractTest, ALostRobotsLookAroundRefinesItsCorrectionAndLeavesTheGridAlone) {
  const testing::SyntheticRoom room = testing::StandardRoom();
  std::vector<v1::SensorFrame> mapped;
  int64_t stamp = 0;
  for (int i = 0; i < 12; ++i) {
    mapped.push_back(testing::FrameToProto(testing::RenderFrame(
        room, testing::TurnedAt({3.0, 2.0}, 2.0 * M_PI * i / 12), stamp += kFrameNs)));
  }
  Stream(mapped);
  const std::string grid_before = Grid().grid().SerializeAsString();

  // The robot believes it is 1 m / -0.5 m and 25 deg off: reported = wrong * true. It reports
  // the loss 10 s after it mapped the room: walls its own frames drew within the scene's
  // untrusted lookback before the loss would not count for its match (MappingEngineTest.
  // ALostRobotsMatchLeavesOutTheWallsItDrewInTheLookback).
  const double yaw = 25.0 * M_PI / 180.0;
  const Eigen::Rotation2Dd turn(yaw);
  const Eigen::Vector2d shift(1.0, -0.5);
  stamp += 10'000'000'000;
  std::vector<v1::SensorFrame> lost;
  for (int i = 0; i < 8; ++i) {
    const CameraPose truth = testing::TurnedAt({1.5, 2.5}, 2.0 * M_PI * i / 8);
    SensorFrame frame = testing::RenderFrame(room, truth, stamp += kFrameNs);
    const Eigen::Vector2d reported = turn * truth.position.head<2>() + shift;
    frame.pose.position = Eigen::Vector3d(reported.x(), reported.y(), truth.position.z());
    frame.pose.orientation =
        Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ())) * truth.orientation;
    v1::SensorFrame proto = testing::FrameToProto(frame);
    proto.set_pose_untrusted(true);
    lost.push_back(proto);
  }
  for (const v1::FrameAck& ack : Stream(lost)) EXPECT_TRUE(ack.accepted()) << ack.error().field();
  v1::GetGridMapResponse after = Grid();
  after.mutable_grid()->set_revision(0);  // frames bump the revision, not the cells
  v1::GetGridMapResponse before;
  ASSERT_TRUE(before.mutable_grid()->ParseFromString(grid_before));
  before.mutable_grid()->set_revision(0);
  EXPECT_EQ(after.grid().SerializeAsString(), before.grid().SerializeAsString());

  // The true correction is wrong^-1; relocalization's coarse answer is 0.15 m and 5 deg off it.
  const Eigen::Rotation2Dd back(-yaw);
  const Eigen::Vector2d truth_shift = -(back * shift);
  v1::MatchLostScanRequest request;
  request.set_robot_id("robot-1");
  request.mutable_coarse()->set_x(truth_shift.x() + 0.15);
  request.mutable_coarse()->set_y(truth_shift.y());
  request.mutable_coarse()->set_yaw(-yaw + 5.0 * M_PI / 180.0);
  v1::MatchLostScanResponse response;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(stub_->MatchLostScan(&context, request, &response).ok());
  }
  EXPECT_TRUE(response.refined());
  EXPECT_GT(response.score(), response.coarse_score());
  EXPECT_GE(response.scan_cells(), 30u);
  EXPECT_NEAR(response.correction().yaw(), -yaw, 1.0 * M_PI / 180.0);
  const Eigen::Vector2d robot =
      Eigen::Rotation2Dd(response.correction().yaw()) * (turn * Eigen::Vector2d(1.5, 2.5) + shift) +
      Eigen::Vector2d(response.correction().x(), response.correction().y());
  EXPECT_LT((robot - Eigen::Vector2d(1.5, 2.5)).norm(), 0.08);

  // Without a coarse pose: the global search over the map finds the same place.
  v1::MatchLostScanRequest global;
  global.set_robot_id("robot-1");
  global.set_global(true);
  v1::MatchLostScanResponse found;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(stub_->MatchLostScan(&context, global, &found).ok());
  }
  EXPECT_TRUE(found.refined()) << found.score() << " vs " << found.runner_up_score() << ", rays "
                               << found.ray_conflicts();
  EXPECT_NEAR(found.correction().yaw(), -yaw, 1.0 * M_PI / 180.0);
  EXPECT_LT(found.ray_conflicts(), 0.1);

  // Bad requests name their field; an unknown robot has no lost scan.
  auto call = [&](const v1::MatchLostScanRequest& r) {
    grpc::ClientContext context;
    v1::MatchLostScanResponse ignored;
    return stub_->MatchLostScan(&context, r, &ignored);
  };
  v1::MatchLostScanRequest bad = request;
  bad.mutable_coarse()->set_yaw(std::numeric_limits<double>::quiet_NaN());
  grpc::Status status = call(bad);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "coarse.yaw");
  bad = request;
  bad.mutable_coarse()->set_x(1e300);
  status = call(bad);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "coarse.x");
  EXPECT_LT(status.error_message().size(), 200u);
  bad = request;
  bad.set_robot_id(std::string(100000, 'r'));
  status = call(bad);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(GetDetail<ErrorInfo>(status)->field(), "robot_id");
  EXPECT_LT(status.error_message().size(), 300u);
  bad = request;
  bad.set_robot_id("robot-2");
  status = call(bad);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(GetDetail<ErrorInfo>(status)->reason(), "NO_LOST_SCAN");
  // A trusted frame ends the loss.
  Stream({RoomFrame(stamp += kFrameNs)});
  EXPECT_EQ(call(request).error_code(), grpc::StatusCode::NOT_FOUND);
}

}  // namespace
}  // namespace semnav::mapping
