// semnav.relocalization.v1.RelocalizationService through gRPC against the real binary:
// build a map, relocalize a transformed subset, align two maps with a known transform,
// and bad input -> named error with state unchanged.
#include <gmock/gmock.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <string>

#include "semnav/common/v1/errors.pb.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/relocalization/eval/scenario.h"
#include "tests/support/service_process.h"

namespace semnav::relocalization {
namespace {

using ::semnav::testing::ServiceProcess;
using ::testing::HasSubstr;
namespace eval = ::semnav::relocalization::eval;

eval::ScenarioParams Scene() {
  eval::ScenarioParams p;
  p.seed = 21;
  p.map_landmarks = 400;
  p.area_m = 30.0;
  p.keyframes = 3;
  p.observed_true = 25;
  p.observed_false = 10;
  p.lookalike_fraction = 0.1;
  return p;
}

void ToProto(const Landmark& l, v1::Landmark* out) {
  out->mutable_position()->set_x(l.position.x());
  out->mutable_position()->set_y(l.position.y());
  out->mutable_position()->set_z(l.position.z());
  out->set_scale_m(l.scale);
  out->mutable_embedding()->Assign(l.descriptor.begin(), l.descriptor.end());
}

Eigen::Isometry3d FromProto(const common::v1::Pose& p) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::Quaterniond(p.orientation().w(), p.orientation().x(), p.orientation().y(),
                                     p.orientation().z())
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(p.position().x(), p.position().y(), p.position().z());
  return pose;
}

double TranslationError(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}
double RotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle() * 180.0 / 3.14159265358979;
}

// The ErrorInfo.field of a failed call ("" when absent).
std::string FieldOf(const grpc::Status& status) {
  const auto info = GetDetail<common::v1::ErrorInfo>(status);
  return info ? info->field() : "";
}

class RelocalizationContractTest : public ::testing::Test {
 protected:
  void SetUp() override { Start({}); }

  void Start(std::vector<std::string> args) {
    process_.reset();
    auto started = ServiceProcess::Start("semnav-relocalization", std::move(args));
    ASSERT_TRUE(started.ok()) << started.status();
    process_ = *std::move(started);
    stub_ = v1::RelocalizationService::NewStub(process_->channel());
  }

  grpc::Status Upsert(const std::string& map_id, const std::vector<Landmark>& landmarks,
                      v1::UpsertLandmarksResponse* response, const std::string& request_id = "") {
    v1::UpsertLandmarksRequest request;
    request.set_map_id(map_id);
    request.set_request_id(request_id);
    for (const Landmark& l : landmarks) ToProto(l, request.add_landmarks());
    grpc::ClientContext context;
    return stub_->UpsertLandmarks(&context, request, response);
  }

  // Streams the whole map; returns the pages read.
  grpc::Status ReadMap(const std::string& map_id, uint32_t page_size,
                       std::vector<v1::GetLandmarkMapResponse>* pages) {
    v1::GetLandmarkMapRequest request;
    request.set_map_id(map_id);
    request.set_page_size(page_size);
    grpc::ClientContext context;
    auto reader = stub_->GetLandmarkMap(&context, request);
    v1::GetLandmarkMapResponse page;
    while (reader->Read(&page)) pages->push_back(page);
    return reader->Finish();
  }

  // (revision, landmark count) of a map, for "state unchanged" checks.
  std::pair<uint64_t, size_t> MapState(const std::string& map_id) {
    std::vector<v1::GetLandmarkMapResponse> pages;
    EXPECT_TRUE(ReadMap(map_id, 0, &pages).ok());
    size_t count = 0;
    for (const auto& p : pages) count += static_cast<size_t>(p.landmarks_size());
    return {pages.empty() ? 0 : pages.front().revision(), count};
  }

  std::unique_ptr<ServiceProcess> process_;
  std::unique_ptr<v1::RelocalizationService::Stub> stub_;
};

TEST_F(RelocalizationContractTest, BuildMapThenRelocalizeATransformedSubset) {
  const eval::Scenario scene = eval::GenerateScenario(Scene());
  const std::vector<Landmark> first(scene.map.begin(), scene.map.begin() + 200);
  const std::vector<Landmark> second(scene.map.begin() + 200, scene.map.end());
  v1::UpsertLandmarksResponse a, b;
  ASSERT_TRUE(Upsert("site", first, &a).ok());
  ASSERT_TRUE(Upsert("site", second, &b).ok());
  EXPECT_EQ(a.revision(), 1u);
  EXPECT_EQ(b.revision(), 2u);
  EXPECT_EQ(a.inserted() + a.merged() + b.inserted() + b.merged(), 400u);
  ASSERT_EQ(b.landmark_ids_size(), 200);

  std::vector<v1::GetLandmarkMapResponse> pages;
  ASSERT_TRUE(ReadMap("site", 150, &pages).ok());
  const size_t stored = a.inserted() + b.inserted();
  EXPECT_EQ(pages.size(), (stored + 149) / 150);
  EXPECT_EQ(pages.front().total_landmarks(), stored);
  EXPECT_EQ(pages.back().revision(), 2u);

  for (const eval::Keyframe& k : scene.keyframes) {
    v1::RelocalizeRequest request;
    request.set_map_id("site");
    for (const Landmark& l : k.observed) ToProto(l, request.add_observed());
    v1::RelocalizeResponse response;
    grpc::ClientContext context;
    const grpc::Status status = stub_->Relocalize(&context, request, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    const v1::PoseSolution& s = response.solution();
    EXPECT_TRUE(s.reliable());
    EXPECT_GE(s.inlier_count(), 15u);
    EXPECT_EQ(response.map_revision(), 2u);
    EXPECT_LT(TranslationError(FromProto(s.map_from_query()), k.map_from_query), 0.1);
    EXPECT_LT(RotationErrorDeg(FromProto(s.map_from_query()), k.map_from_query), 1.0);
  }
}

TEST_F(RelocalizationContractTest, AlignsTwoRobotMapsWithAKnownTransformAsTheyGrow) {
  const eval::ScenarioParams p = Scene();
  const eval::Scenario scene = eval::GenerateScenario(p);
  Eigen::Isometry3d a_from_b = Eigen::Isometry3d::Identity();
  a_from_b.linear() = Eigen::AngleAxisd(-2.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  a_from_b.translation() = Eigen::Vector3d(-7.0, 3.0, 0.2);
  const eval::Keyframe robot_b =
      eval::ObserveRegion(scene, p, {15.0, 15.0, 2.0}, 7.0, a_from_b, 20, 5);
  v1::UpsertLandmarksResponse ignored;
  ASSERT_TRUE(Upsert("robot-a", scene.map, &ignored).ok());
  // Robot B's map grows while the robots explore: align after each upload.
  const size_t half = robot_b.observed.size() / 2;
  const std::vector<Landmark> first(robot_b.observed.begin(), robot_b.observed.begin() + half);
  const std::vector<Landmark> rest(robot_b.observed.begin() + half, robot_b.observed.end());
  for (const std::vector<Landmark>* part : {&first, &rest}) {
    ASSERT_TRUE(Upsert("robot-b", *part, &ignored).ok());
    v1::AlignMapsRequest request;
    request.set_reference_map_id("robot-a");
    request.set_moving_map_id("robot-b");
    v1::AlignMapsResponse response;
    grpc::ClientContext context;
    const grpc::Status status = stub_->AlignMaps(&context, request, &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    EXPECT_TRUE(response.solution().reliable());
    EXPECT_EQ(response.moving_revision(), part == &first ? 1u : 2u);
    // B's frame origin is ~20 m from its landmarks: 0.2 deg of rotation error moves it 7 cm.
    EXPECT_LT(TranslationError(FromProto(response.solution().map_from_query()), a_from_b), 0.15);
    EXPECT_LT(RotationErrorDeg(FromProto(response.solution().map_from_query()), a_from_b), 0.5);
    for (const v1::LandmarkMatch& m : response.solution().matches())
      EXPECT_NE(m.query_landmark_id(), 0u);
  }
}

TEST_F(RelocalizationContractTest, BadUpsertsNameTheFieldAndChangeNothing) {
  const eval::Scenario scene = eval::GenerateScenario(Scene());
  v1::UpsertLandmarksResponse response;
  ASSERT_TRUE(Upsert("m", {scene.map[0], scene.map[1]}, &response).ok());
  const auto before = MapState("m");

  std::vector<Landmark> bad = {scene.map[2], scene.map[3]};
  bad[1].position.y() = std::numeric_limits<double>::quiet_NaN();
  grpc::Status s = Upsert("m", bad, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "landmarks[1].position.y");

  bad = {scene.map[2]};
  bad[0].descriptor.pop_back();
  s = Upsert("m", bad, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "landmarks[0].embedding");
  EXPECT_THAT(s.error_message(), HasSubstr("length"));

  s = Upsert("m", {}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "landmarks");

  s = Upsert("../escape", {scene.map[2]}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "map_id");

  EXPECT_EQ(MapState("m"), before);
}

// Hostile requests from other-language clients: NaN, 1e300, 1 MB strings, oversized lists and
// parameters. Each names its field, keeps the message short and changes no map.
TEST_F(RelocalizationContractTest, HostileRequestsNameTheFieldAndChangeNoMap) {
  const eval::Scenario scene = eval::GenerateScenario(Scene());
  v1::UpsertLandmarksResponse response;
  ASSERT_TRUE(Upsert("m", {scene.map[0], scene.map[1], scene.map[2]}, &response).ok());
  const auto before = MapState("m");
  const std::string megabyte(1 << 20, 'x');
  const auto expect_named = [](const grpc::Status& s, const std::string& field) {
    EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
        << field << ": " << s.error_message();
    EXPECT_EQ(FieldOf(s), field);
    EXPECT_LT(s.error_message().size(), 1024u) << field;
    EXPECT_LT(s.error_details().size(), 2048u) << field;
  };

  std::vector<Landmark> bad = {scene.map[3]};
  bad[0].position.x() = 1e300;
  expect_named(Upsert("m", bad, &response), "landmarks[0].position.x");
  bad = {scene.map[3]};
  bad[0].scale = 1e300;
  expect_named(Upsert("m", bad, &response), "landmarks[0].scale_m");
  bad = {scene.map[3]};
  bad[0].descriptor[0] = std::numeric_limits<float>::max();
  expect_named(Upsert("m", bad, &response), "landmarks[0].embedding");
  expect_named(Upsert(megabyte, {scene.map[3]}, &response), "map_id");
  expect_named(Upsert("m", {scene.map[3]}, &response, megabyte), "request_id");
  expect_named(Upsert("m", std::vector<Landmark>(10001, scene.map[3]), &response), "landmarks");

  v1::RelocalizeRequest relocalize;
  relocalize.set_map_id("m");
  for (int i = 0; i < 3; ++i) ToProto(scene.map[static_cast<size_t>(i)], relocalize.add_observed());
  relocalize.mutable_observed(2)->mutable_position()->set_z(-1e300);
  v1::RelocalizeResponse relocalized;
  {
    grpc::ClientContext context;
    expect_named(stub_->Relocalize(&context, relocalize, &relocalized), "observed[2].position.z");
  }
  v1::AlignMapsRequest align;
  align.set_reference_map_id("m");
  align.set_moving_map_id(megabyte);
  v1::AlignMapsResponse aligned;
  {
    grpc::ClientContext context;
    expect_named(stub_->AlignMaps(&context, align, &aligned), "moving_map_id");
  }
  v1::DeleteLandmarkMapRequest remove;
  remove.set_map_id("m");
  remove.set_request_id(megabyte);
  v1::DeleteLandmarkMapResponse removed;
  {
    grpc::ClientContext context;
    expect_named(stub_->DeleteLandmarkMap(&context, remove, &removed), "request_id");
  }
  std::vector<v1::GetLandmarkMapResponse> pages;
  expect_named(ReadMap("m", 4000000000u, &pages), "page_size");
  EXPECT_TRUE(pages.empty());

  v1::ExtractObjectPointsRequest extract;
  extract.set_top_k(4000000000u);
  v1::HeadTensors* t = extract.mutable_tensors();
  t->set_width(1);
  t->set_height(1);
  t->set_heatmap_channels(1);
  t->add_heatmap(1.0f);
  t->add_offset(0.0f);
  t->add_offset(0.0f);
  t->add_box_size(1.0f);
  t->add_box_size(1.0f);
  t->set_stride_x(4.0);
  t->set_stride_y(4.0);
  v1::ExtractObjectPointsResponse points;
  {
    grpc::ClientContext context;
    expect_named(stub_->ExtractObjectPoints(&context, extract, &points), "top_k");
  }
  extract.set_top_k(0);
  t->set_stride_x(1e300);
  {
    grpc::ClientContext context;
    expect_named(stub_->ExtractObjectPoints(&context, extract, &points), "tensors.stride_x");
  }

  EXPECT_EQ(MapState("m"), before);
}

TEST_F(RelocalizationContractTest, RepeatedRequestIdReturnsTheFirstAnswer) {
  const eval::Scenario scene = eval::GenerateScenario(Scene());
  v1::UpsertLandmarksResponse first, again;
  ASSERT_TRUE(Upsert("m", {scene.map[0]}, &first, "req-1").ok());
  ASSERT_TRUE(Upsert("m", {scene.map[5]}, &again, "req-1").ok());
  EXPECT_EQ(first.SerializeAsString(), again.SerializeAsString());
  EXPECT_EQ(MapState("m"), std::make_pair(uint64_t{1}, size_t{1}));

  auto remove = [&](const std::string& request_id) {
    v1::DeleteLandmarkMapRequest request;
    request.set_map_id("m");
    request.set_request_id(request_id);
    v1::DeleteLandmarkMapResponse response;
    grpc::ClientContext context;
    return stub_->DeleteLandmarkMap(&context, request, &response);
  };
  EXPECT_TRUE(remove("del-1").ok());
  EXPECT_TRUE(remove("del-1").ok());  // the retry gets the first answer
  const grpc::Status again_deleted = remove("del-2");
  EXPECT_EQ(again_deleted.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(FieldOf(again_deleted), "map_id");
}

TEST_F(RelocalizationContractTest, BadRelocalizeAndAlignNameTheField) {
  const eval::Scenario scene = eval::GenerateScenario(Scene());
  v1::UpsertLandmarksResponse ignored;
  ASSERT_TRUE(Upsert("m", scene.map, &ignored).ok());
  const auto before = MapState("m");

  auto relocalize = [&](const std::string& map_id, const std::vector<Landmark>& observed,
                        v1::RelocalizeResponse* response) {
    v1::RelocalizeRequest request;
    request.set_map_id(map_id);
    for (const Landmark& l : observed) ToProto(l, request.add_observed());
    grpc::ClientContext context;
    return stub_->Relocalize(&context, request, response);
  };
  v1::RelocalizeResponse response;
  grpc::Status s = relocalize("nope", scene.keyframes[0].observed, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(FieldOf(s), "map_id");

  s = relocalize("m", {}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "observed");

  std::vector<Landmark> observed = scene.keyframes[0].observed;
  observed[4].descriptor.push_back(1.0f);
  s = relocalize("m", observed, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "observed[4].embedding");

  observed = scene.keyframes[0].observed;
  observed[2].position.x() = std::numeric_limits<double>::infinity();
  s = relocalize("m", observed, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "observed[2].position.x");

  s = relocalize("m", {scene.keyframes[0].observed[0], scene.keyframes[0].observed[1]}, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_THAT(s.error_message(), HasSubstr("too few landmarks"));
  const auto info = GetDetail<common::v1::ErrorInfo>(s);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->reason(), "RELOCALIZATION_FAILED");

  v1::AlignMapsRequest align;
  align.set_reference_map_id("m");
  align.set_moving_map_id("missing");
  v1::AlignMapsResponse aligned;
  grpc::ClientContext context;
  s = stub_->AlignMaps(&context, align, &aligned);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(FieldOf(s), "moving_map_id");

  EXPECT_EQ(MapState("m"), before);
}

TEST_F(RelocalizationContractTest, ExtractsObjectPointsFromTensors) {
  v1::ExtractObjectPointsRequest request;
  v1::HeadTensors* t = request.mutable_tensors();
  t->set_width(3);
  t->set_height(2);
  t->set_heatmap_channels(1);
  for (float v : {-4.f, -4.f, -4.f, -4.f, 2.f, -4.f}) t->add_heatmap(v);  // peak at (1, 1)
  for (int i = 0; i < 12; ++i) t->add_offset(i == 4 ? 0.5f : 0.0f);       // du = 0.5 at the peak
  for (int i = 0; i < 12; ++i) t->add_box_size(1.0f);
  t->set_stride_x(4.0);
  t->set_stride_y(4.0);
  request.set_top_k(1);
  v1::ExtractObjectPointsResponse response;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(stub_->ExtractObjectPoints(&context, request, &response).ok());
  }
  ASSERT_EQ(response.points_size(), 1);
  EXPECT_DOUBLE_EQ(response.points(0).u(), 6.0);  // (1 + 0.5) * 4
  EXPECT_DOUBLE_EQ(response.points(0).v(), 4.0);
  EXPECT_EQ(response.points(0).label(), 0);

  t->mutable_heatmap()->RemoveLast();
  grpc::ClientContext bad_context;
  grpc::Status s = stub_->ExtractObjectPoints(&bad_context, request, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(FieldOf(s), "tensors.heatmap");

  v1::ExtractObjectPointsRequest image_request;
  image_request.mutable_image()->set_width(4);
  grpc::ClientContext image_context;
  s = stub_->ExtractObjectPoints(&image_context, image_request, &response);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_EQ(FieldOf(s), "image");
}

TEST_F(RelocalizationContractTest, ExtractsObjectPointsFromAnImageWithTheOnnxDetector) {
  const std::string python = SEMNAV_RELOC_PYTHON3;
  if (python.empty() || std::system((python + " -c 'import onnx' 2>/dev/null").c_str()) != 0) {
    GTEST_SKIP() << "python3-onnx is not installed (apt install python3-onnx)";
  }
  const std::string model = ::testing::TempDir() + "/contract_centernet.onnx";
  ASSERT_EQ(
      std::system((python + " " SEMNAV_RELOC_TESTDATA "/make_centernet_onnx.py " + model).c_str()),
      0);
  const std::string config = ::testing::TempDir() + "/reloc_onnx.yaml";
  std::ofstream(config)
      << "relocalization:\n  detector:\n    model_path: " << model
      << "\n    input_width: 8\n    input_height: 8\n    feature_output: features\n";
  Start({"--config", config});

  // 8 x 8 RGB8 image: G = 128 everywhere, R = 255 at pixel (5, 2) (see the model script).
  std::string pixels(8 * 8 * 3, '\0');
  for (size_t i = 0; i < 64; ++i) pixels[i * 3 + 1] = static_cast<char>(128);
  pixels[(2 * 8 + 5) * 3] = static_cast<char>(255);
  v1::ExtractObjectPointsRequest request;
  request.mutable_image()->set_width(8);
  request.mutable_image()->set_height(8);
  request.mutable_image()->set_encoding(common::v1::IMAGE_ENCODING_RGB8);
  request.mutable_image()->set_data(pixels);
  request.set_top_k(1);
  v1::ExtractObjectPointsResponse response;
  grpc::ClientContext context;
  const grpc::Status status = stub_->ExtractObjectPoints(&context, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  ASSERT_EQ(response.points_size(), 1);
  EXPECT_NEAR(response.points(0).u(), 5.25, 1e-4);  // (5 + 0.25) * stride 1
  EXPECT_NEAR(response.points(0).v(), 1.75, 1e-4);
  EXPECT_NEAR(response.points(0).score(), 1.0 / (1.0 + std::exp(-3.0)), 1e-5);
  ASSERT_EQ(response.points(0).embedding_size(), 4);
  EXPECT_NEAR(response.points(0).embedding(3), 0.5, 1e-5);
  EXPECT_EQ(response.points(0).label(), 0);  // R = 1 is the largest feature
}

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(RelocalizationContractTest, PersistedMapSurvivesRestartAndCorruptionIsDataLoss) {
  const std::string dir = ::testing::TempDir() + "/reloc_contract_store";
  std::filesystem::remove_all(dir);
  const std::string config = ::testing::TempDir() + "/reloc_contract.yaml";
  std::ofstream(config) << "relocalization:\n  storage_dir: " << dir << "\n";
  Start({"--config", config});
  const eval::Scenario scene = eval::GenerateScenario(Scene());
  v1::UpsertLandmarksResponse ignored;
  ASSERT_TRUE(Upsert("kept", {scene.map[0], scene.map[1]}, &ignored).ok());
  ASSERT_TRUE(Upsert("broken", {scene.map[2]}, &ignored).ok());

  Start({"--config", config});  // restart: maps come back from disk
  EXPECT_EQ(MapState("kept"), std::make_pair(uint64_t{1}, size_t{2}));

  process_.reset();
  const std::string broken = dir + "/broken.lmap";
  std::filesystem::resize_file(broken, std::filesystem::file_size(broken) - 3);
  const std::string corrupt_bytes = ReadAll(broken);
  Start({"--config", config});
  std::vector<v1::GetLandmarkMapResponse> pages;
  grpc::Status s = ReadMap("broken", 0, &pages);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::DATA_LOSS);
  EXPECT_EQ(FieldOf(s), "map_id");
  s = Upsert("broken", {scene.map[3]}, &ignored);
  EXPECT_EQ(s.error_code(), grpc::StatusCode::DATA_LOSS);
  EXPECT_EQ(ReadAll(broken), corrupt_bytes);  // nothing replaced
  EXPECT_EQ(MapState("kept"), std::make_pair(uint64_t{1}, size_t{2}));
}

}  // namespace
}  // namespace semnav::relocalization
