// Writes the binary seed inputs of tests/fuzz/corpus/ (the text ones are written by hand):
// a small saved map, map file, landmark map file, OctoMap, world, and one request per RPC in
// the rpc_* harnesses' format (rpc_harness.h). Run from the fuzz build after changing a format:
//   build/release/bin/fuzz_make_seeds tests/fuzz/corpus   (or build/fuzz/bin/...)
#include <google/protobuf/descriptor.h>
#include <google/protobuf/dynamic_message.h>
#include <google/protobuf/text_format.h>
#include <octomap/OcTree.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "clients/sim/core/world_yaml.h"
#include "clients/sim/worlds/indoor_generator.h"
#include "semnav/common/v1/metrics.pb.h"
#include "semnav/mapping/v1/mapping_service.pb.h"
#include "semnav/modelproxy/v1/modelproxy.pb.h"
#include "semnav/planning/v1/planning_service.pb.h"
#include "semnav/reasoning/v1/operator.pb.h"
#include "semnav/reasoning/v1/robot_session.pb.h"
#include "semnav/relocalization/v1/relocalization.pb.h"
#include "services/common/storage/durable_file.h"
#include "services/mapping/core/map_serialization.h"
#include "services/mapping/core/map_store.h"
#include "services/relocalization/core/landmark_map.h"
#include "services/relocalization/core/landmark_map_file.h"

namespace {

namespace fs = std::filesystem;
fs::path root;

void Write(const std::string& harness, const std::string& name, const std::string& bytes) {
  fs::create_directories(root / harness);
  std::ofstream(root / harness / name, std::ios::binary) << bytes;
}

std::string LittleEndian(uint64_t value, int bytes) {
  std::string out;
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
  return out;
}

octomap::OcTree SmallTree() {
  octomap::OcTree tree(0.2);
  for (double x = 0; x < 2.0; x += 0.2) {
    for (double y = 0; y < 2.0; y += 0.2)
      tree.updateNode(octomap::point3d(x, y, 0.1f), true);  // floor
    for (double z = 0.3; z < 1.2; z += 0.2)
      tree.updateNode(octomap::point3d(x, 1.9f, z), true);  // a wall
  }
  tree.updateNode(octomap::point3d(1.0f, 1.0f, 0.5f), false);
  return tree;
}

void MapSeeds() {
  const octomap::OcTree tree = SmallTree();
  std::vector<semnav::mapping::SceneObject> objects(2);
  objects[0].id = 1;
  objects[0].label = "chair";
  objects[0].position = {1.0, 1.0, 0.4};
  objects[0].size = {0.5, 0.5, 0.8};
  objects[0].score = 0.8;
  objects[0].detection_count = 3;
  objects[0].embedding = {1, 0, 0, 0};
  objects[0].label_scores = {{"chair", 2.4}};
  objects[1].id = 2;
  objects[1].label = "cup";
  objects[1].position = {1.5, 1.2, 0.8};
  objects[1].region_id = 0;
  const std::map<std::string, std::vector<Eigen::Vector3f>> points = {
      {"chair", {{1, 1, 0.4f}, {1.1f, 1, 0.4f}}}};
  semnav::mapping::SavedGrid grid;
  grid.resolution_m = 0.2;
  grid.cells = {{0, 0, 0.85f, 10, false}, {1, 9, 2.0f, 200, true}, {-3, 4, -0.4f, 0, false}};
  const std::string payload = semnav::mapping::SerializeMap(tree, objects, 3, points, &grid);
  Write("map_payload", "small_map", payload);
  Write("map_payload", "small_map_without_grid",
        semnav::mapping::SerializeMap(tree, objects, 3, points));
  Write("map_store_file", "small_map_wrapped", "\x01" + payload);
  Write("map_store_file", "small_map_file",
        std::string(1, '\0') + semnav::storage::FrameWithChecksum("SNMAP1\n", payload));
  std::ostringstream bt;
  tree.writeBinaryConst(bt);
  Write("octomap_import", "small.bt", bt.str());
}

void LandmarkSeeds() {
  std::vector<semnav::relocalization::Landmark> landmarks(3);
  for (int i = 0; i < 3; ++i) {
    landmarks[i].id = i + 1;
    landmarks[i].position = {1.0 + i, 2.0 * i, 0.5};
    landmarks[i].scale = 0.4;
    landmarks[i].descriptor = {0, 0, 0, 0};
    landmarks[i].descriptor[i] = 1;
    landmarks[i].observations = 2;
  }
  const semnav::relocalization::LandmarkMap map(landmarks, 4, 7);
  const fs::path path = fs::temp_directory_path() / "semnav-seed.snlm";
  if (!semnav::relocalization::WriteLandmarkMapFile(path, map).ok()) std::abort();
  std::ifstream in(path, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  fs::remove(path);
  Write("landmark_map_file", "three_landmarks", std::string(1, '\0') + file);
  Write("landmark_map_file", "three_landmarks_unsummed", "\x01" + file.substr(0, file.size() - 8));
}

void WorldSeeds() {
  Write("world_yaml", "indoor_home.yaml",
        semnav::sim::WorldToYaml(
            semnav::sim::GenerateIndoor("home", semnav::sim::IndoorOptions(), 7)));
}

// Text-format escapes: 16 depth pixels of 2.0 m (float32), 64 free cells, 32 explored cells.
std::string Repeat(const std::string& text, int count) {
  std::string out;
  for (int i = 0; i < count; ++i) out += text;
  return out;
}
const std::string kGrid =
    "grid { resolution: 0.5 width: 8 height: 8 layers { kind: GRID_LAYER_KIND_OCCUPANCY data: \"" +
    Repeat("\\000", 64) + "\" } layers { kind: GRID_LAYER_KIND_EXPLORED data: \"" +
    Repeat("\\001", 32) + Repeat("\\000", 32) + "\" } }";
const std::string kLandmarks = [] {
  std::string text;
  const char* corners[] = {"x: 1 y: 1 z: 0", "x: 4 y: 1 z: 0", "x: 1 y: 5 z: 1"};
  const char* embeddings[] = {"1, 0, 0, 0", "0, 1, 0, 0", "0, 0, 1, 0"};
  for (int i = 0; i < 3; ++i) {
    text += std::string("@ { position { ") + corners[i] + " } scale_m: 0.5 embedding: [ " +
            embeddings[i] + " ] observations: 1 } ";
  }
  return text;
}();
std::string Landmarks(const std::string& field) {
  std::string text = kLandmarks;
  for (size_t at = text.find('@'); at != std::string::npos; at = text.find('@'))
    text.replace(at, 1, field);
  return text;
}

// (method, text of each message); streaming methods get several messages.
struct RequestSeed {
  std::string method;
  std::vector<std::string> messages;
};

void RpcSeeds(const std::string& harness, const std::vector<std::string>& services,
              const std::vector<RequestSeed>& seeds) {
  std::vector<const google::protobuf::MethodDescriptor*> methods;
  for (const std::string& name : services) {
    const auto* service =
        google::protobuf::DescriptorPool::generated_pool()->FindServiceByName(name);
    if (service == nullptr) {
      std::fprintf(stderr, "no descriptor for %s\n", name.c_str());
      std::abort();
    }
    for (int i = 0; i < service->method_count(); ++i) methods.push_back(service->method(i));
  }
  google::protobuf::DynamicMessageFactory factory;
  for (size_t index = 0; index < methods.size(); ++index) {
    const auto* method = methods[index];
    Write(harness, method->name() + "_empty", std::string(1, static_cast<char>(index)));
    for (const RequestSeed& seed : seeds) {
      if (seed.method != method->name()) continue;
      std::string input(1, static_cast<char>(index));
      for (const std::string& text : seed.messages) {
        std::unique_ptr<google::protobuf::Message> message(
            factory.GetPrototype(method->input_type())->New());
        if (!google::protobuf::TextFormat::ParseFromString(text, message.get())) {
          std::fprintf(stderr, "bad seed text for %s\n", method->full_name().c_str());
          std::abort();
        }
        const std::string bytes = message->SerializeAsString();
        if (method->client_streaming()) input += LittleEndian(bytes.size(), 2);
        input += bytes;
      }
      Write(harness, method->name() + "_sensible", input);
    }
  }
}

void AllRpcSeeds() {
  // Referencing each generated file links its descriptors into the generated pool.
  for (const google::protobuf::Descriptor* type :
       {semnav::mapping::v1::GetGridMapRequest::descriptor(),
        semnav::common::v1::GetMetricsRequest::descriptor(),
        semnav::planning::v1::PlanPathRequest::descriptor(),
        semnav::relocalization::v1::RelocalizeRequest::descriptor(),
        semnav::modelproxy::v1::CompleteRequest::descriptor(),
        semnav::reasoning::v1::SubmitInstructionRequest::descriptor(),
        semnav::reasoning::v1::ConnectRequest::descriptor()}) {
    (void)type;
  }
  const std::string depth = Repeat("\\000\\000\\000@", 16);
  RpcSeeds(
      "rpc_mapping", {"semnav.mapping.v1.MappingService", "semnav.common.v1.MetricsService"},
      {{"StreamFrames",
        {"frame { header { stamp { seconds: 1 } frame_id: \"camera\" robot_id: \"r1\" } "
         "intrinsics { width: 4 height: 4 fx: 2 fy: 2 cx: 2 cy: 2 } "
         "depth { width: 4 height: 4 encoding: IMAGE_ENCODING_DEPTH_32FC1_M data: \"" +
         depth +
         "\" } "
         "camera_pose { position { x: 1 y: 1 z: 1 } orientation { w: 1 } } "
         "detections { label: \"chair\" score: 0.9 box { x_min: 1 y_min: 1 x_max: 3 y_max: 3 } "
         "embedding: [ 1, 0, 0, 0 ] } lidar_points { x: 2 y: 1 z: 1 } }"}},
       {"GetGridMap", {"window { min { x: 0 y: 0 } max { x: 2 y: 2 } }"}},
       {"WatchGridMap", {"window { min { x: 0 y: 0 } max { x: 2 y: 2 } } min_interval_ms: 50"}},
       {"GetOccupancy", {"min { x: 0 y: 0 z: 0 } max { x: 1 y: 1 z: 1 }"}},
       {"QueryObjects", {"labels: \"chair\" near { x: 1 y: 1 z: 0 } near_radius: 5"}},
       {"SaveMap", {"request_id: \"s1\" map_id: \"fuzz\""}},
       {"LoadMap", {"request_id: \"l1\" map_id: \"fuzz\""}},
       {"DeleteMap", {"request_id: \"d1\" map_id: \"fuzz\""}},
       {"ResetMap", {"request_id: \"r1\""}}});
  RpcSeeds(
      "rpc_planning", {"semnav.planning.v1.PlanningService"},
      {{"PlanPath",
        {"source { " + kGrid +
         " } start { x: 0.6 y: 0.6 } goal { x: 3.2 y: 3.2 } "
         "robot_radius_m: 0.1 goal_tolerance_m: 0.2"}},
       {"ExtractFrontiers", {"source { " + kGrid + " } robot { x: 0.6 y: 0.6 }"}},
       {"SelectExplorationGoal", {"source { " + kGrid + " } robot { x: 0.6 y: 0.6 }"}},
       {"SmoothTrajectory",
        {"source { " + kGrid + " } path { x: 0.6 y: 0.6 } path { x: 3.2 y: 1.6 }"}},
       {"ScoreFrontiers",
        {"frontiers { centroid { x: 2 y: 2 } anchor { x: 2 y: 2 } size_cells: 3 path_distance_m: 2 "
         "} "
         "robot { x: 0.5 y: 0.5 } semantics { objects { label: \"chair\" position { x: 1 y: 1 } "
         "relevance: 0.5 relation: 0.5 cooccurrence: 0.5 } visited { x: 0 y: 0 } } weights { "
         "distance: 1 }"}}});
  RpcSeeds("rpc_relocalization", {"semnav.relocalization.v1.RelocalizationService"},
           {{"UpsertLandmarks", {"map_id: \"fuzz\" request_id: \"u1\" " + Landmarks("landmarks")}},
            {"GetLandmarkMap", {"map_id: \"fuzz\" page_size: 10"}},
            {"Relocalize", {"map_id: \"fuzz\" " + Landmarks("observed")}},
            {"AlignMaps", {"reference_map_id: \"fuzz\" moving_map_id: \"fuzz\""}},
            {"DeleteLandmarkMap", {"map_id: \"other\" request_id: \"d1\""}}});
  RpcSeeds("rpc_modelproxy", {"semnav.modelproxy.v1.ModelProxyService"},
           {{"Complete",
             {"messages { role: ROLE_USER parts { text: \"{\\\"task\\\": \\\"match_target\\\", "
              "\\\"target\\\": \\\"red mug\\\", "
              "\\\"candidates\\\": [{\\\"id\\\": \\\"1\\\", \\\"label\\\": \\\"cup\\\"}]}\" } } "
              "response_format: RESPONSE_FORMAT_JSON_OBJECT"}},
            {"Embed", {"texts: \"chair\" texts: \"red cup\""}}});
  RpcSeeds("rpc_gateway",
           {"semnav.reasoning.v1.OperatorService", "semnav.reasoning.v1.RobotSessionService"},
           {{"SubmitInstruction",
             {"request_id: \"i1\" robot_id: \"r1\" instruction: \"find the chair\""}},
            {"AcquireLease",
             {"request_id: \"a1\" robot_id: \"r1\" holder: \"fuzz\" ttl { seconds: 5 }"}},
            {"DecomposeInstruction",
             {"instruction: \"go to the kitchen and find the red cup near the chair\""}},
            {"ResolveTarget", {"robot_id: \"r1\" text: \"the chair near the door\""}},
            {"EmergencyStop", {"robot_id: \"r1\""}},
            {"Connect",
             {"hello { robot_id: \"r1\" software_version: \"fuzz\" }",
              "state { header { stamp { seconds: 1 } robot_id: \"r1\" } pose { position { x: 1 y: "
              "1 z: 0 } "
              "orientation { w: 1 } } battery_fraction: 0.5 }"}}});
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <tests/fuzz/corpus>\n", argv[0]);
    return 2;
  }
  root = argv[1];
  MapSeeds();
  LandmarkSeeds();
  WorldSeeds();
  AllRpcSeeds();
  return 0;
}
