// Contract test: semnav-mapping fills the relocalization service's landmark maps by itself (the
// real binaries on loopback): live scene-graph landmarks under mapping.landmarks.live_map_id,
// and SaveMap / LoadMap carrying the landmark map under the same map id as the occupancy map.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/mapping/testing/frame_proto.h"
#include "tests/support/service_process.h"

namespace semnav::mapping {
namespace {

namespace rv1 = semnav::relocalization::v1;

constexpr int64_t kFrameNs = 100'000'000;
const std::vector<float> kTableEmbedding = {0.0f, 3.0f, 0.0f, 4.0f};  // unit (0, 0.6, 0, 0.8)

// A room frame with a "table" detection around the static box.
v1::SensorFrame RoomFrame(int64_t stamp) {
  return testing::StandardRoomFrameWithTable(stamp, kTableEmbedding);
}

class MappingLandmarksContractTest : public ::testing::Test {
 protected:
  // `relocalization_address` empty = start a relocalization service and use it.
  // `publisher_keys`: extra lines of mapping.landmarks (the push's timing).
  void StartServices(std::string relocalization_address = "",
                     const std::string& publisher_keys = "    interval_s: 0.1\n") {
    store_ = ::testing::TempDir() + "/mapping_landmarks_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::filesystem::remove_all(store_);
    if (relocalization_address.empty()) {
      absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> reloc =
          semnav::testing::ServiceProcess::Start("semnav-relocalization");
      ASSERT_TRUE(reloc.ok()) << reloc.status();
      relocalization_ = *std::move(reloc);
      relocalization_address = relocalization_->address();
      reloc_stub_ = rv1::RelocalizationService::NewStub(relocalization_->channel());
    }
    const std::string config = store_ + ".yaml";
    std::ofstream(config)
        << "mapping:\n  store_directory: " << store_
        << "\n  live_snapshot_interval_s: 0\n  landmarks:\n    labels: [chair, table]\n"
        << "    embedding_dim: 4\n    live_map_id: robot_x\n"
        << publisher_keys
        // settle_s 0: the frames here are 0.1 s apart; the push itself is under test.
        << "    deadline_ms: 500\n    settle_s: 0\n    relocalization: {address: \""
        << relocalization_address << "\"}\n";
    absl::StatusOr<std::unique_ptr<semnav::testing::ServiceProcess>> mapping =
        semnav::testing::ServiceProcess::Start("semnav-mapping", {"--config", config});
    ASSERT_TRUE(mapping.ok()) << mapping.status();
    mapping_ = *std::move(mapping);
    stub_ = v1::MappingService::NewStub(mapping_->channel());
  }

  void StreamTableFrames(int count) {
    grpc::ClientContext context;
    auto stream = stub_->StreamFrames(&context);
    for (int i = 0; i < count; ++i) {
      v1::StreamFramesRequest request;
      *request.mutable_frame() = RoomFrame(++frames_sent_ * kFrameNs);
      ASSERT_TRUE(stream->Write(request));
      v1::StreamFramesResponse response;
      ASSERT_TRUE(stream->Read(&response));
      ASSERT_TRUE(response.has_ack()) << "frame " << i << " was not accepted";
    }
    stream->WritesDone();
    ASSERT_TRUE(stream->Finish().ok());
  }

  // The landmarks of relocalization's map `map_id` now, and how the read ended.
  std::vector<rv1::Landmark> ReadLandmarks(const std::string& map_id, grpc::Status* status) {
    rv1::GetLandmarkMapRequest request;
    request.set_map_id(map_id);
    grpc::ClientContext context;
    auto reader = reloc_stub_->GetLandmarkMap(&context, request);
    rv1::GetLandmarkMapResponse page;
    std::vector<rv1::Landmark> out;
    while (reader->Read(&page))
      out.insert(out.end(), page.landmarks().begin(), page.landmarks().end());
    *status = reader->Finish();
    return out;
  }

  // The landmarks of relocalization's map `map_id`, waiting up to 10 s for it to appear.
  std::vector<rv1::Landmark> AwaitLandmarks(const std::string& map_id) {
    const absl::Time give_up = absl::Now() + absl::Seconds(10);
    while (absl::Now() < give_up) {
      grpc::Status status;
      std::vector<rv1::Landmark> out = ReadLandmarks(map_id, &status);
      if (status.ok() && !out.empty()) return out;
      absl::SleepFor(absl::Milliseconds(50));
    }
    ADD_FAILURE() << "landmark map " << map_id << " never reached relocalization";
    return {};
  }

  grpc::Status Call(const std::function<grpc::Status(grpc::ClientContext*)>& call) {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
    return call(&context);
  }

  int64_t frames_sent_ = 0;
  std::string store_;
  std::unique_ptr<semnav::testing::ServiceProcess> relocalization_;
  std::unique_ptr<semnav::testing::ServiceProcess> mapping_;
  std::unique_ptr<v1::MappingService::Stub> stub_;
  std::unique_ptr<rv1::RelocalizationService::Stub> reloc_stub_;
};

// [chair share, table share | 0.5 x unit embedding]: hand-checked from the frames above.
void ExpectTableDescriptor(const rv1::Landmark& l) {
  ASSERT_EQ(l.embedding_size(), 6);
  EXPECT_FLOAT_EQ(l.embedding(0), 0.0f);
  EXPECT_FLOAT_EQ(l.embedding(1), 1.0f);
  EXPECT_NEAR(l.embedding(2), 0.0f, 1e-5);
  EXPECT_NEAR(l.embedding(3), 0.3f, 1e-5);
  EXPECT_NEAR(l.embedding(4), 0.0f, 1e-5);
  EXPECT_NEAR(l.embedding(5), 0.4f, 1e-5);
}

TEST_F(MappingLandmarksContractTest, LiveSceneGraphFillsTheLandmarkMapWithoutAnOperator) {
  ASSERT_NO_FATAL_FAILURE(StartServices());
  StreamTableFrames(4);  // one instance seen 4 times >= min_detections 3
  // A push may come after the third frame (the instance is stable from then): wait for the one
  // that has all four.
  std::vector<rv1::Landmark> live;
  for (int i = 0; i < 100; ++i) {
    live = AwaitLandmarks("robot_x");
    if (live.size() == 1 && live[0].observations() == 4) break;
    absl::SleepFor(absl::Milliseconds(50));
  }
  ASSERT_EQ(live.size(), 1u);
  ExpectTableDescriptor(live[0]);
  EXPECT_NEAR(live[0].position().x(), 3.2, 0.5);
  EXPECT_NEAR(live[0].position().y(), 1.3, 0.5);
  EXPECT_GT(live[0].scale_m(), 0.0);
  EXPECT_EQ(live[0].observations(), 4u);

  // More frames of the same table replace its landmark, they do not add one.
  StreamTableFrames(2);
  std::vector<rv1::Landmark> again;
  for (int i = 0; i < 100; ++i) {  // the next push within a few 0.1 s intervals
    again = AwaitLandmarks("robot_x");
    if (again.size() != 1 || again[0].observations() == 6) break;
    absl::SleepFor(absl::Milliseconds(50));
  }
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].id(), live[0].id());
  EXPECT_EQ(again[0].observations(), 6u);
}

// The lock-step simulator's setting: once a frame's ack is back, the live landmark map already
// holds what that frame made of the scene; no background interval (an hour here) decides. Before,
// the kidnapped group's first relocalization answer depended on when the push thread had run.
TEST_F(MappingLandmarksContractTest, PushWithFramesUpdatesTheLandmarkMapBeforeTheAck) {
  ASSERT_NO_FATAL_FAILURE(StartServices("", "    interval_s: 3600\n    push_with_frames: true\n"));
  auto live_now = [&] {
    grpc::Status status;
    std::vector<rv1::Landmark> out = ReadLandmarks("robot_x", &status);
    EXPECT_TRUE(status.ok() || status.error_code() == grpc::StatusCode::NOT_FOUND)
        << status.error_message();
    return out;
  };
  StreamTableFrames(2);  // below min_detections 3: nothing yet
  EXPECT_TRUE(live_now().empty());
  StreamTableFrames(1);
  std::vector<rv1::Landmark> live = live_now();
  ASSERT_EQ(live.size(), 1u);
  EXPECT_EQ(live[0].observations(), 3u);
  ExpectTableDescriptor(live[0]);
  StreamTableFrames(1);
  live = live_now();
  ASSERT_EQ(live.size(), 1u);
  EXPECT_EQ(live[0].observations(), 4u);

  // ResetMap empties it before it answers, too.
  v1::ResetMapRequest reset;
  reset.set_request_id("reset-sync");
  v1::ResetMapResponse reset_done;
  ASSERT_TRUE(
      Call([&](grpc::ClientContext* c) { return stub_->ResetMap(c, reset, &reset_done); }).ok());
  EXPECT_TRUE(live_now().empty());
}

// Regression (kidnapped episodes with --landmarks mapping): ResetMap left the old scene's
// landmarks in the live landmark map, so the next building was matched against the last one.
TEST_F(MappingLandmarksContractTest, ResetMapEmptiesTheLiveLandmarkMap) {
  ASSERT_NO_FATAL_FAILURE(StartServices());
  StreamTableFrames(4);
  ASSERT_EQ(AwaitLandmarks("robot_x").size(), 1u);
  v1::ResetMapRequest reset;
  reset.set_request_id("reset-1");
  v1::ResetMapResponse reset_done;
  ASSERT_TRUE(
      Call([&](grpc::ClientContext* c) { return stub_->ResetMap(c, reset, &reset_done); }).ok());
  bool emptied = false;
  for (int i = 0; i < 100 && !emptied; ++i) {
    rv1::GetLandmarkMapRequest request;
    request.set_map_id("robot_x");
    grpc::ClientContext context;
    auto reader = reloc_stub_->GetLandmarkMap(&context, request);
    rv1::GetLandmarkMapResponse page;
    int count = 0;
    while (reader->Read(&page)) count += page.landmarks_size();
    const grpc::Status status = reader->Finish();
    emptied = status.error_code() == grpc::StatusCode::NOT_FOUND || (status.ok() && count == 0);
    if (!emptied) absl::SleepFor(absl::Milliseconds(50));
  }
  EXPECT_TRUE(emptied);
}

TEST_F(MappingLandmarksContractTest, UnstableInstancesAreNoLandmarks) {
  ASSERT_NO_FATAL_FAILURE(StartServices());
  StreamTableFrames(2);  // seen twice: below min_detections
  absl::SleepFor(absl::Milliseconds(600));
  rv1::GetLandmarkMapRequest request;
  request.set_map_id("robot_x");
  grpc::ClientContext context;
  auto reader = reloc_stub_->GetLandmarkMap(&context, request);
  rv1::GetLandmarkMapResponse page;
  while (reader->Read(&page)) {
  }
  EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::NOT_FOUND);
}

TEST_F(MappingLandmarksContractTest, SaveMapAndLoadMapCarryTheLandmarkMapUnderTheSameMapId) {
  ASSERT_NO_FATAL_FAILURE(StartServices());
  StreamTableFrames(4);
  v1::SaveMapRequest save;
  save.set_request_id("save-kitchen");
  save.set_map_id("kitchen");
  v1::SaveMapResponse saved;
  ASSERT_TRUE(Call([&](grpc::ClientContext* c) { return stub_->SaveMap(c, save, &saved); }).ok());
  EXPECT_TRUE(std::filesystem::exists(store_ + "/kitchen.snmap"));
  EXPECT_TRUE(std::filesystem::exists(store_ + "/kitchen.lmap"));
  const std::vector<rv1::Landmark> pushed = AwaitLandmarks("kitchen");
  ASSERT_EQ(pushed.size(), 1u);
  ExpectTableDescriptor(pushed[0]);

  // Relocalization forgets the map, mapping starts over; loading "kitchen" brings both back.
  rv1::DeleteLandmarkMapRequest forget;
  forget.set_map_id("kitchen");
  rv1::DeleteLandmarkMapResponse forgotten;
  ASSERT_TRUE(Call([&](grpc::ClientContext* c) {
                return reloc_stub_->DeleteLandmarkMap(c, forget, &forgotten);
              }).ok());
  v1::ResetMapRequest reset;
  reset.set_request_id("reset-1");
  v1::ResetMapResponse was_reset;
  ASSERT_TRUE(
      Call([&](grpc::ClientContext* c) { return stub_->ResetMap(c, reset, &was_reset); }).ok());
  v1::LoadMapRequest load;
  load.set_request_id("load-kitchen");
  load.set_map_id("kitchen");
  v1::LoadMapResponse loaded;
  ASSERT_TRUE(Call([&](grpc::ClientContext* c) { return stub_->LoadMap(c, load, &loaded); }).ok());
  const std::vector<rv1::Landmark> restored = AwaitLandmarks("kitchen");
  ASSERT_EQ(restored.size(), 1u);
  EXPECT_DOUBLE_EQ(restored[0].position().x(), pushed[0].position().x());
  EXPECT_DOUBLE_EQ(restored[0].position().y(), pushed[0].position().y());
  EXPECT_DOUBLE_EQ(restored[0].position().z(), pushed[0].position().z());
  EXPECT_DOUBLE_EQ(restored[0].scale_m(), pushed[0].scale_m());
  ExpectTableDescriptor(restored[0]);

  // Deleting the map deletes its landmark file too.
  v1::DeleteMapRequest remove;
  remove.set_request_id("delete-kitchen");
  remove.set_map_id("kitchen");
  v1::DeleteMapResponse removed;
  ASSERT_TRUE(
      Call([&](grpc::ClientContext* c) { return stub_->DeleteMap(c, remove, &removed); }).ok());
  EXPECT_FALSE(std::filesystem::exists(store_ + "/kitchen.lmap"));
}

TEST_F(MappingLandmarksContractTest, MappingKeepsWorkingWithoutRelocalization) {
  // A port nothing listens on.
  ASSERT_NO_FATAL_FAILURE(StartServices("127.0.0.1:1"));
  StreamTableFrames(4);
  absl::SleepFor(absl::Milliseconds(300));  // a few failed pushes
  StreamTableFrames(1);
  v1::SaveMapRequest save;
  save.set_request_id("save-offline");
  save.set_map_id("offline");
  v1::SaveMapResponse saved;
  ASSERT_TRUE(Call([&](grpc::ClientContext* c) { return stub_->SaveMap(c, save, &saved); }).ok());
  EXPECT_TRUE(std::filesystem::exists(store_ + "/offline.lmap"));
}

TEST_F(MappingLandmarksContractTest, BadLandmarkConfigStopsTheServiceNamingTheKey) {
  const std::string config = ::testing::TempDir() + "/mapping_landmarks_bad.yaml";
  std::ofstream(config) << "mapping:\n  landmarks:\n    labels: [chair, chair]\n";
  absl::StatusOr<semnav::testing::ProcessResult> run = semnav::testing::RunToCompletion(
      "semnav-mapping", {"--config", config, "--listen", "127.0.0.1:0"});
  ASSERT_TRUE(run.ok()) << run.status();
  EXPECT_NE(run->exit_code, 0);
  EXPECT_NE(run->output.find("mapping.landmarks.labels[1]"), std::string::npos) << run->output;
}

}  // namespace
}  // namespace semnav::mapping
