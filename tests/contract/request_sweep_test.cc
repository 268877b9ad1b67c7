// A request sweep generated from the descriptors: every RPC of every semnav service, started
// for real, gets the empty message, one message per reachable scalar field set to a hostile
// value (NaN, +-inf, 1e300, INT64_MAX, -1, an unknown enum, 1 MiB strings), a truncated body and
// seeded random bytes, as raw bytes through grpc::GenericStub. After every call the server must
// be alive and SERVING, the call must have ended (streams that stay open are cancelled by the
// test), the status must not be INTERNAL/UNKNOWN, an INVALID_ARGUMENT must carry an ErrorInfo
// naming the field, messages stay short, and a rejected call must not have changed the map.
// Mutations start from a valid request where the method has one (SensibleBases), so NaN, an
// infinity, 1e300 or an unknown enum must be rejected, and by the mutated field's name. A body
// that does not parse must be INVALID_ARGUMENT "could not be parsed" (unary and server streams).
// SEMNAV_SWEEP_ONLY=<Service>/<Method>:<mutation prefix> replays one case.
#include <google/protobuf/descriptor.h>
#include <google/protobuf/dynamic_message.h>
#include <google/protobuf/message.h>
#include <google/protobuf/text_format.h>
#include <grpcpp/generic/generic_stub.h>
#include <grpcpp/grpcpp.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_replace.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "semnav/common/v1/errors.pb.h"
#include "semnav/common/v1/metrics.grpc.pb.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "semnav/modelproxy/v1/modelproxy.grpc.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "semnav/reasoning/v1/operator.grpc.pb.h"
#include "semnav/reasoning/v1/robot_session.grpc.pb.h"
#include "semnav/relocalization/v1/relocalization.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "tests/support/service_process.h"

namespace semnav::testing {
namespace {

using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using google::protobuf::MethodDescriptor;
using google::protobuf::Reflection;

// Known failures of services fixed by other engineers, as "<Service>/<Method>:<mutation>"
// prefixes (e.g. "semnav.reasoning.v1.OperatorService/SubmitInstruction:instruction" covers
// every mutation of that field). Mapping and planning must never appear here. Whoever fixes a
// service empties its entries; the test prints entries that no longer fail.
const std::vector<std::string> kPendingFixes = {};

constexpr int kMaxFieldDepth = 4;
constexpr size_t kHugeStringBytes = 1 << 20;
// A status message may say what is wrong, never carry the request back.
constexpr size_t kMaxMessageBytes = 1100;
constexpr absl::Duration kCallDeadline = absl::Seconds(5);
// Streams still open after this are answering a valid request: the test cancels them.
constexpr absl::Duration kOpenStreamGrace = absl::Milliseconds(250);
// No number a service stores or returns is this large (coordinates are limited to 1e5 m;
// timestamps travel as integers): 1e300 or infinity leaking through would exceed it.
constexpr double kMaxPlausibleNumber = 1e15;

struct SweptBinary {
  std::string binary;
  std::vector<std::string> services;
  std::string config_yaml;  // written to a file and passed as --config when not empty
};

void PrintTo(const SweptBinary& swept, std::ostream* out) { *out << swept.binary; }

std::vector<SweptBinary> SweptBinaries() {
  // Referencing each generated file links its descriptors into the generated pool.
  const std::vector<const google::protobuf::FileDescriptor*> files = {
      semnav::mapping::v1::GetGridMapRequest::descriptor()->file(),
      semnav::planning::v1::PlanPathRequest::descriptor()->file(),
      semnav::relocalization::v1::RelocalizeRequest::descriptor()->file(),
      semnav::modelproxy::v1::CompleteRequest::descriptor()->file(),
      semnav::reasoning::v1::SubmitInstructionRequest::descriptor()->file(),
      semnav::reasoning::v1::ConnectRequest::descriptor()->file(),
      semnav::common::v1::GetMetricsRequest::descriptor()->file(),
  };
  (void)files;
  return {
      {"semnav-mapping",
       {"semnav.mapping.v1.MappingService", "semnav.common.v1.MetricsService"},
       "mapping:\n  store_directory: STORE\n  watch_min_interval_ms: 50\n"},
      {"semnav-planning", {"semnav.planning.v1.PlanningService"}, ""},
      {"semnav-relocalization", {"semnav.relocalization.v1.RelocalizationService"}, ""},
      {"semnav-model-proxy", {"semnav.modelproxy.v1.ModelProxyService"}, ""},
      {"semnav-gateway",
       {"semnav.reasoning.v1.OperatorService", "semnav.reasoning.v1.RobotSessionService"},
       ""},
  };
}

// A request worth mutating beyond the empty message: mutations of a valid frame or plan reach
// the checks behind "frame has no depth" or "no grid". UNIQUE is replaced per call, so frames of
// different calls never look like one robot going back in time and request ids never repeat.
// Three landmarks that span a frame, as the text of a repeated field `field`.
std::string ThreeLandmarks(absl::string_view field) {
  std::string text;
  const char* corners[] = {"x: 1 y: 1 z: 0", "x: 4 y: 1 z: 0", "x: 1 y: 5 z: 1"};
  const char* embeddings[] = {"1, 0, 0, 0", "0, 1, 0, 0", "0, 0, 1, 0"};
  for (int i = 0; i < 3; ++i) {
    absl::StrAppend(&text, field, " { position { ", corners[i], " } scale_m: 0.5 embedding: [ ",
                    embeddings[i], " ] observations: 1 } ");
  }
  return text;
}

const std::map<std::string, std::string>& SensibleBases() {
  // 8 x 8 cells of 0.5 m, all free; rows 0-3 explored, so there is a frontier at y = 2 m.
  // The quotes split across the raw strings below are one data string each: not reformatted.
  // clang-format off
  static const std::string kGrid = absl::StrCat(
      R"pb(grid {
             resolution: 0.5
             width: 8
             height: 8
             layers { kind: GRID_LAYER_KIND_OCCUPANCY data: ")pb",
      "@ZEROS@", R"pb(" }
             layers { kind: GRID_LAYER_KIND_EXPLORED data: ")pb", "@EXPLORED@", R"pb(" }
           })pb");
  // clang-format on
  static const auto* bases = new std::map<std::string, std::string>{
      {"semnav.mapping.v1.MappingService/StreamFrames",
       R"pb(frame {
              header {
                stamp { seconds: 1 }
                frame_id: "camera"
                robot_id: "@UNIQUE@"
              }
              intrinsics { width: 4 height: 4 fx: 2 fy: 2 cx: 2 cy: 2 }
              depth { width: 4 height: 4 encoding: IMAGE_ENCODING_DEPTH_32FC1_M data: "@DEPTH@" }
              camera_pose {
                position { x: 1 y: 1 z: 1 }
                orientation { w: 1 }
              }
              detections {
                label: "chair"
                score: 0.9
                box { x_min: 1 y_min: 1 x_max: 3 y_max: 3 }
                embedding: [ 1, 0, 0, 0 ]
              }
              lidar_points { x: 2 y: 1 z: 1 }
            })pb"},
      {"semnav.mapping.v1.MappingService/GetOccupancy", R"pb(min { x: 0 y: 0 z: 0 }
                                                             max { x: 1 y: 1 z: 1 })pb"},
      {"semnav.mapping.v1.MappingService/QueryObjects", R"pb(labels: "chair"
                                                             near { x: 1 y: 1 z: 0 }
                                                             near_radius: 5)pb"},
      {"semnav.mapping.v1.MappingService/SaveMap", R"pb(request_id: "@UNIQUE@" map_id: "sweep")pb"},
      {"semnav.mapping.v1.MappingService/LoadMap", R"pb(request_id: "@UNIQUE@" map_id: "sweep")pb"},
      {"semnav.mapping.v1.MappingService/DeleteMap",
       R"pb(request_id: "@UNIQUE@" map_id: "sweep")pb"},
      {"semnav.mapping.v1.MappingService/ResetMap", R"pb(request_id: "@UNIQUE@")pb"},
      {"semnav.mapping.v1.MappingService/MatchLostScan", R"pb(robot_id: "sweep"
                                                              coarse { x: 1 y: 1 yaw: 0.5 })pb"},
      {"semnav.planning.v1.PlanningService/PlanPath", absl::StrCat("source {", kGrid, R"pb(}
                                                                                           start { x: 0.6 y: 0.6 }
                    goal { x: 3.2 y: 3.2 }
                    robot_radius_m: 0.1
                    goal_tolerance_m: 0.2)pb")},
      {"semnav.planning.v1.PlanningService/ExtractFrontiers",
       absl::StrCat("source {", kGrid, "} robot { x: 0.6 y: 0.6 }")},
      {"semnav.planning.v1.PlanningService/SelectExplorationGoal",
       absl::StrCat("source {", kGrid, "} robot { x: 0.6 y: 0.6 }")},
      {"semnav.planning.v1.PlanningService/SmoothTrajectory",
       absl::StrCat("source {", kGrid, "} path { x: 0.6 y: 0.6 } path { x: 3.2 y: 1.6 }")},
      {"semnav.relocalization.v1.RelocalizationService/UpsertLandmarks",
       absl::StrCat(R"pb(map_id: "sweep" request_id: "@UNIQUE@")pb", ThreeLandmarks("landmarks"))},
      {"semnav.relocalization.v1.RelocalizationService/GetLandmarkMap", R"pb(map_id: "sweep"
                                                                             page_size: 10)pb"},
      {"semnav.relocalization.v1.RelocalizationService/Relocalize",
       absl::StrCat(R"pb(map_id: "sweep")pb", ThreeLandmarks("observed"))},
      {"semnav.modelproxy.v1.ModelProxyService/Complete",
       R"pb(messages {
              role: ROLE_USER
              parts { text: "hello" }
            })pb"},
      {"semnav.modelproxy.v1.ModelProxyService/Embed", R"pb(texts: "chair")pb"},
      {"semnav.reasoning.v1.OperatorService/SubmitInstruction",
       R"pb(request_id: "@UNIQUE@" robot_id: "sweep-robot" instruction: "find the chair")pb"},
      {"semnav.reasoning.v1.OperatorService/AcquireLease", R"pb(request_id: "@UNIQUE@"
                                                                robot_id: "@UNIQUE@"
                                                                holder: "sweep"
                                                                ttl { seconds: 5 })pb"},
      {"semnav.reasoning.v1.OperatorService/DecomposeInstruction",
       R"pb(instruction: "find the chair")pb"},
      {"semnav.reasoning.v1.RobotSessionService/Connect",
       R"pb(state {
              header {
                stamp { seconds: 1 }
                robot_id: "@UNIQUE@"
              }
              pose {
                position { x: 1 y: 1 z: 0 }
                orientation { w: 1 }
              }
              battery_fraction: 0.5
            })pb"},
      {"semnav.planning.v1.PlanningService/ScoreFrontiers",
       R"pb(frontiers {
              centroid { x: 2 y: 2 }
              anchor { x: 2 y: 2 }
              size_cells: 3
              path_distance_m: 2
            }
            robot { x: 0.5 y: 0.5 }
            semantics {
              objects {
                label: "chair"
                position { x: 1 y: 1 }
                relevance: 0.5
                relation: 0.5
                cooccurrence: 0.5
              }
              visited { x: 0 y: 0 }
            }
            weights { distance: 1 })pb"},
  };
  return *bases;
}

// Bidi streams whose every message needs an opening one: the mutated message is sent second.
const std::map<std::string, std::string>& SessionPreambles() {
  static const auto* preambles = new std::map<std::string, std::string>{
      {"semnav.reasoning.v1.RobotSessionService/Connect",
       R"pb(hello { robot_id: "@UNIQUE@" software_version: "sweep" })pb"},
  };
  return *preambles;
}

// Text-format escapes of the bases' binary fields: 16 depth pixels of 2.0 m (float32), 64 free
// cells, 32 explored then 32 unexplored cells.
const std::string kDepthBytes = [] {
  std::string out;
  for (int i = 0; i < 16; ++i) out += "\\000\\000\\000@";
  return out;
}();
const std::string kZeroBytes = [] {
  std::string out;
  for (int i = 0; i < 64; ++i) out += "\\000";
  return out;
}();
const std::string kExploredBytes = [] {
  std::string out;
  for (int i = 0; i < 64; ++i) out += i < 32 ? "\\001" : "\\000";
  return out;
}();

// One request to send: its label (the allow-list key after the method), the field it mutates
// ("" for whole-body requests) and whether the bytes parse as the request type.
struct Request {
  std::string label;
  std::string field;
  std::string bytes;
  bool parses = true;
  // NaN, an infinity, 1e300 (3e38 in a float) or an unknown enum: no door may accept it.
  bool must_be_rejected = false;
  // The request every mutation starts from ("sensible" when the method has one, else "empty").
  bool is_base = false;
  // The outermost message the mutation had to create (absent from the base), e.g. "window" for
  // "window.min.z" on an empty request: its other fields are defaults, which may be what fails.
  std::string created_root;
  // Sent first on a bidi stream that needs it (a robot session's hello); empty = none.
  std::string preamble;
};

// The outermost message on `path` that `base` does not hold ("" when all exist).
std::string CreatedRoot(const Message& base, const std::vector<const FieldDescriptor*>& path) {
  const Message* message = &base;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Reflection* reflection = message->GetReflection();
    const FieldDescriptor* field = path[i];
    if (field->is_repeated() ? reflection->FieldSize(*message, field) == 0
                             : !reflection->HasField(*message, field)) {
      return field->name();
    }
    message = field->is_repeated() ? &reflection->GetRepeatedMessage(*message, field, 0)
                                   : &reflection->GetMessage(*message, field);
  }
  return "";
}

using FieldPath = std::vector<const FieldDescriptor*>;

std::string PathName(const FieldPath& path) {
  std::string name;
  for (const FieldDescriptor* field : path) {
    if (!name.empty()) name += ".";
    name += field->name();
    if (field->is_repeated()) name += "[0]";
  }
  return name;
}

// Every scalar field reachable from `type`, through nested messages up to kMaxFieldDepth.
void CollectScalarPaths(const Descriptor* type, FieldPath& prefix, std::vector<FieldPath>& out) {
  for (int i = 0; i < type->field_count(); ++i) {
    const FieldDescriptor* field = type->field(i);
    prefix.push_back(field);
    if (field->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE) {
      out.push_back(prefix);
    } else if (static_cast<int>(prefix.size()) < kMaxFieldDepth) {
      CollectScalarPaths(field->message_type(), prefix, out);
    }
    prefix.pop_back();
  }
}

// The message holding the last field of `path`, creating the first element of repeated ones.
Message* ParentOf(Message* root, const FieldPath& path) {
  Message* message = root;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const Reflection* reflection = message->GetReflection();
    const FieldDescriptor* field = path[i];
    if (!field->is_repeated()) {
      message = reflection->MutableMessage(message, field);
    } else if (reflection->FieldSize(*message, field) == 0) {
      message = reflection->AddMessage(message, field);
    } else {
      message = reflection->MutableRepeatedMessage(message, field, 0);
    }
  }
  return message;
}

// Hostile values for one scalar field, as (label, setter) pairs.
using Setter = std::function<void(Message*, const FieldDescriptor*)>;
std::vector<std::pair<std::string, Setter>> HostileValues(const FieldDescriptor* field) {
  auto set_or_add = [](auto set, auto add) {
    return [set, add](Message* message, const FieldDescriptor* f) {
      const Reflection* reflection = message->GetReflection();
      if (f->is_repeated()) {
        reflection->ClearField(message, f);
        add(reflection, message, f);
      } else {
        set(reflection, message, f);
      }
    };
  };
  auto number = [&](double value) {
    return set_or_add(
        [value](const Reflection* r, Message* m, const FieldDescriptor* f) {
          if (f->cpp_type() == FieldDescriptor::CPPTYPE_DOUBLE)
            r->SetDouble(m, f, value);
          else
            r->SetFloat(m, f, static_cast<float>(value));
        },
        [value](const Reflection* r, Message* m, const FieldDescriptor* f) {
          if (f->cpp_type() == FieldDescriptor::CPPTYPE_DOUBLE)
            r->AddDouble(m, f, value);
          else
            r->AddFloat(m, f, static_cast<float>(value));
        });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  switch (field->cpp_type()) {
    case FieldDescriptor::CPPTYPE_DOUBLE:
      return {{"nan", number(nan)},
              {"+inf", number(inf)},
              {"-inf", number(-inf)},
              {"1e300", number(1e300)}};
    case FieldDescriptor::CPPTYPE_FLOAT:
      return {{"nan", number(nan)},
              {"+inf", number(inf)},
              {"-inf", number(-inf)},
              {"3e38", number(3e38)}};
    case FieldDescriptor::CPPTYPE_INT32:
    case FieldDescriptor::CPPTYPE_INT64: {
      auto integer = [&](int64_t value) {
        return set_or_add(
            [value](const Reflection* r, Message* m, const FieldDescriptor* f) {
              if (f->cpp_type() == FieldDescriptor::CPPTYPE_INT64)
                r->SetInt64(m, f, value);
              else
                r->SetInt32(m, f, static_cast<int32_t>(value));
            },
            [value](const Reflection* r, Message* m, const FieldDescriptor* f) {
              if (f->cpp_type() == FieldDescriptor::CPPTYPE_INT64)
                r->AddInt64(m, f, value);
              else
                r->AddInt32(m, f, static_cast<int32_t>(value));
            });
      };
      const int64_t max = field->cpp_type() == FieldDescriptor::CPPTYPE_INT64
                              ? std::numeric_limits<int64_t>::max()
                              : std::numeric_limits<int32_t>::max();
      return {{"max", integer(max)}, {"-1", integer(-1)}};
    }
    case FieldDescriptor::CPPTYPE_UINT32:
    case FieldDescriptor::CPPTYPE_UINT64:
      // -1 on the wire is the maximum of an unsigned field.
      return {{"max", set_or_add(
                          [](const Reflection* r, Message* m, const FieldDescriptor* f) {
                            if (f->cpp_type() == FieldDescriptor::CPPTYPE_UINT64)
                              r->SetUInt64(m, f, std::numeric_limits<uint64_t>::max());
                            else
                              r->SetUInt32(m, f, std::numeric_limits<uint32_t>::max());
                          },
                          [](const Reflection* r, Message* m, const FieldDescriptor* f) {
                            if (f->cpp_type() == FieldDescriptor::CPPTYPE_UINT64)
                              r->AddUInt64(m, f, std::numeric_limits<uint64_t>::max());
                            else
                              r->AddUInt32(m, f, std::numeric_limits<uint32_t>::max());
                          })}};
    case FieldDescriptor::CPPTYPE_STRING: {
      const std::string huge(kHugeStringBytes, 'x');
      return {{"1MiB", set_or_add([huge](const Reflection* r, Message* m,
                                         const FieldDescriptor* f) { r->SetString(m, f, huge); },
                                  [huge](const Reflection* r, Message* m,
                                         const FieldDescriptor* f) { r->AddString(m, f, huge); })}};
    }
    case FieldDescriptor::CPPTYPE_ENUM:
      // Proto3 enums are open: an unknown number arrives as is.
      if (field->file()->syntax() != google::protobuf::FileDescriptor::SYNTAX_PROTO3) return {};
      return {
          {"enum9999", set_or_add([](const Reflection* r, Message* m,
                                     const FieldDescriptor* f) { r->SetEnumValue(m, f, 9999); },
                                  [](const Reflection* r, Message* m, const FieldDescriptor* f) {
                                    r->AddEnumValue(m, f, 9999);
                                  })}};
    default:
      return {};  // bools have no hostile value
  }
}

// Plausible values everywhere (depth 2), for a body worth truncating.
void FillPlausibly(Message* message, int depth) {
  const Reflection* reflection = message->GetReflection();
  const Descriptor* type = message->GetDescriptor();
  for (int i = 0; i < type->field_count(); ++i) {
    const FieldDescriptor* field = type->field(i);
    if (field->is_repeated() || field->real_containing_oneof() != nullptr) continue;
    switch (field->cpp_type()) {
      case FieldDescriptor::CPPTYPE_MESSAGE:
        if (depth < 2) FillPlausibly(reflection->MutableMessage(message, field), depth + 1);
        break;
      case FieldDescriptor::CPPTYPE_STRING:
        reflection->SetString(message, field, "sweep");
        break;
      case FieldDescriptor::CPPTYPE_DOUBLE:
        reflection->SetDouble(message, field, 1.0);
        break;
      case FieldDescriptor::CPPTYPE_FLOAT:
        reflection->SetFloat(message, field, 1.0f);
        break;
      case FieldDescriptor::CPPTYPE_INT32:
        reflection->SetInt32(message, field, 1);
        break;
      case FieldDescriptor::CPPTYPE_INT64:
        reflection->SetInt64(message, field, 1);
        break;
      case FieldDescriptor::CPPTYPE_UINT32:
        reflection->SetUInt32(message, field, 1);
        break;
      case FieldDescriptor::CPPTYPE_UINT64:
        reflection->SetUInt64(message, field, 1);
        break;
      case FieldDescriptor::CPPTYPE_BOOL:
        reflection->SetBool(message, field, true);
        break;
      case FieldDescriptor::CPPTYPE_ENUM:
        if (field->enum_type()->value_count() > 1) {
          reflection->SetEnum(message, field, field->enum_type()->value(1));
        }
        break;
    }
  }
}

std::unique_ptr<Message> NewMessage(const Descriptor* type) {
  return std::unique_ptr<Message>(
      google::protobuf::MessageFactory::generated_factory()->GetPrototype(type)->New());
}

// A base's text with its placeholders filled in for request `request_index`.
std::string Render(absl::string_view text, int method_index, size_t request_index) {
  return absl::StrReplaceAll(
      text, {{"@UNIQUE@", absl::StrCat("sweep-", method_index, "-", request_index)},
             {"@DEPTH@", kDepthBytes},
             {"@EXPLORED@", kExploredBytes},
             {"@ZEROS@", kZeroBytes}});
}

std::vector<Request> SweepRequests(const MethodDescriptor* method, int method_index) {
  const Descriptor* type = method->input_type();
  std::vector<Request> requests;
  requests.push_back({"empty", "", "", true, false, true, "", ""});

  const auto base_text =
      SensibleBases().find(absl::StrCat(method->service()->full_name(), "/", method->name()));
  auto base = [&]() {
    std::unique_ptr<Message> message = NewMessage(type);
    if (base_text != SensibleBases().end()) {
      const std::string text = Render(base_text->second, method_index, requests.size());
      EXPECT_TRUE(google::protobuf::TextFormat::ParseFromString(text, message.get()))
          << method->full_name();
    }
    return message;
  };
  if (base_text != SensibleBases().end()) {
    requests.front().is_base = false;
    requests.push_back({"sensible", "", base()->SerializeAsString(), true, false, true, "", ""});
  }

  std::vector<FieldPath> paths;
  FieldPath prefix;
  CollectScalarPaths(type, prefix, paths);
  for (const FieldPath& path : paths) {
    const std::string created_root = CreatedRoot(*base(), path);
    for (const auto& [value_label, setter] : HostileValues(path.back())) {
      std::unique_ptr<Message> message = base();
      setter(ParentOf(message.get(), path), path.back());
      const std::string field = PathName(path);
      // An unknown enum number selects no behaviour: taking it for some default hides a bug.
      const bool unrepresentable = value_label == "nan" || absl::EndsWith(value_label, "inf") ||
                                   value_label == "1e300" || value_label == "3e38" ||
                                   value_label == "enum9999";
      requests.push_back({absl::StrCat(field, "=", value_label), field,
                          message->SerializeAsString(), true, unrepresentable, false, created_root,
                          ""});
    }
  }

  std::unique_ptr<Message> plausible = base();
  if (base_text == SensibleBases().end()) FillPlausibly(plausible.get(), 0);
  std::string whole = plausible->SerializeAsString();
  // Dropping the last byte always leaves the last field incomplete; a message type without
  // fields gets field 1 announcing 5 bytes and carrying 2.
  std::string truncated = whole.empty() ? std::string(
                                              "\x0a\x05"
                                              "ab",
                                              4)
                                        : whole.substr(0, whole.size() - 1);
  requests.push_back({"truncated", "", truncated, NewMessage(type)->ParseFromString(truncated),
                      false, false, "", ""});

  std::mt19937 random(20261124u + static_cast<unsigned>(method_index));
  std::string noise(48, '\0');
  for (char& byte : noise) byte = static_cast<char>(random() & 0xff);
  requests.push_back(
      {"random", "", noise, NewMessage(type)->ParseFromString(noise), false, false, "", ""});

  const auto preamble =
      SessionPreambles().find(absl::StrCat(method->service()->full_name(), "/", method->name()));
  if (preamble != SessionPreambles().end()) {
    for (size_t i = 0; i < requests.size(); ++i) {
      std::unique_ptr<Message> first = NewMessage(type);
      EXPECT_TRUE(google::protobuf::TextFormat::ParseFromString(
          Render(preamble->second, method_index, i), first.get()));
      requests[i].preamble = first->SerializeAsString();
    }
  }
  return requests;
}

struct CallOutcome {
  grpc::Status status;
  std::vector<std::string> responses;
  bool cancelled_by_test = false;
  bool finished_in_time = true;
};

// One call with raw bytes, the same way for unary, server- and bidi-streaming methods: one
// message, WritesDone, read until the end (or cancel a stream still open after the grace).
CallOutcome CallRaw(const std::shared_ptr<grpc::Channel>& channel, const std::string& path,
                    const std::string& preamble, const std::string& bytes, bool may_stay_open) {
  CallOutcome outcome;
  grpc::GenericStub stub(channel);
  grpc::CompletionQueue queue;
  grpc::ClientContext context;
  const absl::Time deadline = absl::Now() + kCallDeadline;
  context.set_deadline(absl::ToChronoTime(deadline));
  std::unique_ptr<grpc::GenericClientAsyncReaderWriter> call =
      stub.PrepareCall(&context, path, &queue);
  // One operation is outstanding at a time, so the next event is always the one awaited.
  auto await = [&](absl::Time until) {
    void* tag = nullptr;
    bool ok = false;
    const auto status = queue.AsyncNext(&tag, &ok, absl::ToChronoTime(until));
    if (status == grpc::CompletionQueue::TIMEOUT) return std::optional<bool>();
    return std::optional<bool>(ok);
  };
  const absl::Time hard_limit = deadline + absl::Seconds(2);
  auto await_or_fail = [&]() {
    std::optional<bool> ok = await(hard_limit);
    if (!ok) outcome.finished_in_time = false;
    return ok.value_or(false);
  };
  call->StartCall(nullptr);
  if (!await_or_fail()) {
    // Fall through to Finish: the status says why.
  }
  for (const std::string* message : {&preamble, &bytes}) {
    if (message == &preamble && preamble.empty()) continue;
    grpc::Slice slice(*message);
    grpc::ByteBuffer buffer(&slice, 1);
    call->Write(buffer, nullptr);
    await_or_fail();
  }
  call->WritesDone(nullptr);
  await_or_fail();
  const absl::Time stream_until = absl::Now() + kOpenStreamGrace;
  while (outcome.finished_in_time) {
    grpc::ByteBuffer received;
    call->Read(&received, nullptr);
    std::optional<bool> ok = await(may_stay_open ? stream_until : hard_limit);
    if (!ok && may_stay_open) {
      outcome.cancelled_by_test = true;
      context.TryCancel();
      ok = await(hard_limit);
    }
    if (!ok) outcome.finished_in_time = false;
    if (!ok.value_or(false)) break;
    std::vector<grpc::Slice> slices;
    std::string response;
    if (received.Dump(&slices).ok()) {
      for (const grpc::Slice& part : slices) {
        response.append(reinterpret_cast<const char*>(part.begin()), part.size());
      }
    }
    outcome.responses.push_back(std::move(response));
  }
  if (!outcome.finished_in_time) context.TryCancel();
  call->Finish(&outcome.status, nullptr);
  if (!await(hard_limit + absl::Seconds(2))) outcome.finished_in_time = false;
  queue.Shutdown();
  void* tag = nullptr;
  bool ok = false;
  while (queue.Next(&tag, &ok)) {
  }
  return outcome;
}

// Numbers no service should store or return (see kMaxPlausibleNumber), with their paths.
void FindImplausibleNumbers(const Message& message, const std::string& prefix,
                            std::vector<std::string>& found) {
  const Reflection* reflection = message.GetReflection();
  std::vector<const FieldDescriptor*> fields;
  reflection->ListFields(message, &fields);
  for (const FieldDescriptor* field : fields) {
    const std::string name = prefix.empty() ? field->name() : prefix + "." + field->name();
    const int count = field->is_repeated() ? reflection->FieldSize(message, field) : 1;
    for (int i = 0; i < count; ++i) {
      const std::string at = field->is_repeated() ? absl::StrCat(name, "[", i, "]") : name;
      double value = 0.0;
      switch (field->cpp_type()) {
        case FieldDescriptor::CPPTYPE_MESSAGE:
          FindImplausibleNumbers(field->is_repeated()
                                     ? reflection->GetRepeatedMessage(message, field, i)
                                     : reflection->GetMessage(message, field),
                                 at, found);
          continue;
        case FieldDescriptor::CPPTYPE_DOUBLE:
          value = field->is_repeated() ? reflection->GetRepeatedDouble(message, field, i)
                                       : reflection->GetDouble(message, field);
          break;
        case FieldDescriptor::CPPTYPE_FLOAT:
          value = field->is_repeated() ? reflection->GetRepeatedFloat(message, field, i)
                                       : reflection->GetFloat(message, field);
          break;
        default:
          continue;
      }
      if (!std::isfinite(value) || std::abs(value) > kMaxPlausibleNumber) {
        found.push_back(absl::StrCat(at, "=", value));
      }
    }
  }
}

// ErrorInfo messages a stream answered with in-band (e.g. a rejected frame's ack).
void FindErrorInfos(const Message& message, std::vector<common::v1::ErrorInfo>& found) {
  if (message.GetDescriptor() == common::v1::ErrorInfo::descriptor()) {
    common::v1::ErrorInfo info;
    info.CopyFrom(message);
    found.push_back(info);
    return;
  }
  const Reflection* reflection = message.GetReflection();
  std::vector<const FieldDescriptor*> fields;
  reflection->ListFields(message, &fields);
  for (const FieldDescriptor* field : fields) {
    if (field->cpp_type() != FieldDescriptor::CPPTYPE_MESSAGE || field->is_map()) continue;
    const int count = field->is_repeated() ? reflection->FieldSize(message, field) : 1;
    for (int i = 0; i < count; ++i) {
      FindErrorInfos(field->is_repeated() ? reflection->GetRepeatedMessage(message, field, i)
                                          : reflection->GetMessage(message, field),
                     found);
    }
  }
}

// "detections[0].embedding[0]" -> "detections.embedding".
std::string WithoutIndexes(absl::string_view path) {
  std::string out;
  bool in_index = false;
  for (char c : path) {
    if (c == '[') in_index = true;
    if (!in_index) out += c;
    if (c == ']') in_index = false;
  }
  return out;
}

// Whether an error's field is about the mutated one: the same path, a containing message
// ("window" for a window's cell budget) or the same path relative to a nested message (a frame's
// ack names "pose.position.x" for "frame.camera_pose.position.x").
bool NamesMutatedField(absl::string_view error_field, const Request& request) {
  const std::string error = WithoutIndexes(error_field);
  const std::string field = WithoutIndexes(request.field);
  if (error.empty()) return false;
  // The error's path, or a containing one, ends at a component boundary of the mutated path.
  for (size_t at = field.find(error); at != std::string::npos; at = field.find(error, at + 1)) {
    const size_t end = at + error.size();
    if (end == field.size() || field[end] == '.') return true;
  }
  if (absl::StartsWith(error, field + ".")) return true;
  // Inside a message the mutation created, a default sibling may be the one that fails.
  const std::string root = request.created_root;
  return !root.empty() &&
         (error == root || absl::StartsWith(error, root + ".") ||
          absl::StrContains(error, "." + root + ".") || absl::EndsWith(error, "." + root));
}

// "" while the process runs, else how it ended.
std::string HowProcessEnded(pid_t pid) {
  siginfo_t info{};
  // WNOWAIT: look without reaping, so ServiceProcess can still Terminate() it.
  if (::waitid(P_PID, pid, &info, WEXITED | WNOHANG | WNOWAIT) != 0) return "gone";
  if (info.si_pid == 0) return "";
  if (info.si_code == CLD_EXITED) return absl::StrCat("exited with ", info.si_status);
  return absl::StrCat("killed by signal ", info.si_status, " (", ::strsignal(info.si_status), ")");
}

class RequestSweepTest : public ::testing::TestWithParam<SweptBinary> {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) / ("sweep_" + GetParam().binary);
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    StartService();
  }

  void StartService() {
    process_.reset();
    std::vector<std::string> args;
    if (!GetParam().config_yaml.empty()) {
      const std::string config = (dir_ / "config.yaml").string();
      std::ofstream(config) << absl::StrReplaceAll(GetParam().config_yaml,
                                                   {{"STORE", (dir_ / "store").string()}});
      args = {"--config", config};
    }
    absl::StatusOr<std::unique_ptr<ServiceProcess>> started =
        ServiceProcess::Start(GetParam().binary, args);
    ASSERT_TRUE(started.ok()) << started.status();
    process_ = *std::move(started);
    channel_ = process_->channel();
  }

  bool is_mapping() const { return GetParam().binary == "semnav-mapping"; }

  // The revisions of the live map (grid, scene graph); empty for other services.
  std::vector<uint64_t> MapRevisions() {
    if (!is_mapping()) return {};
    auto stub = semnav::mapping::v1::MappingService::NewStub(channel_);
    semnav::mapping::v1::GetGridMapResponse grid;
    semnav::mapping::v1::GetSceneGraphResponse graph;
    grpc::ClientContext grid_context, graph_context;
    grid_context.set_deadline(absl::ToChronoTime(absl::Now() + kCallDeadline));
    graph_context.set_deadline(absl::ToChronoTime(absl::Now() + kCallDeadline));
    const grpc::Status grid_status = stub->GetGridMap(&grid_context, {}, &grid);
    const grpc::Status graph_status = stub->GetSceneGraph(&graph_context, {}, &graph);
    EXPECT_TRUE(grid_status.ok()) << grid_status.error_message();
    EXPECT_TRUE(graph_status.ok()) << graph_status.error_message();
    std::vector<std::string> implausible;
    FindImplausibleNumbers(grid, "grid", implausible);
    FindImplausibleNumbers(graph, "graph", implausible);
    if (!implausible.empty()) {
      implausible.resize(std::min<size_t>(3, implausible.size()));
      last_map_numbers_ = absl::StrJoin(implausible, ", ");
    }
    return {grid.grid().revision(), graph.graph().revision()};
  }

  std::filesystem::path dir_;
  std::unique_ptr<ServiceProcess> process_;
  std::shared_ptr<grpc::Channel> channel_;
  std::string last_map_numbers_;
};

TEST_P(RequestSweepTest, EveryRpcSurvivesHostileRequests) {
  ASSERT_NE(process_, nullptr);
  const absl::Time started = absl::Now();
  std::map<std::string, std::string> failures;  // key -> what went wrong
  int calls = 0;
  int method_index = 0;
  std::vector<std::string> methods_swept;
  std::vector<std::string> rejected_bases;

  for (const std::string& service_name : GetParam().services) {
    const google::protobuf::ServiceDescriptor* service =
        google::protobuf::DescriptorPool::generated_pool()->FindServiceByName(service_name);
    ASSERT_NE(service, nullptr) << service_name;
    for (int m = 0; m < service->method_count(); ++m, ++method_index) {
      const MethodDescriptor* method = service->method(m);
      const std::string method_key = absl::StrCat(service_name, "/", method->name());
      const std::string path = absl::StrCat("/", method_key);
      const bool single_request = !method->client_streaming();
      const bool may_stay_open = method->server_streaming();
      methods_swept.push_back(method_key);
      bool base_accepted = false;  // set by the base request, which comes before any mutation
      for (const Request& request : SweepRequests(method, method_index)) {
        const std::string key = absl::StrCat(method_key, ":", request.label);
        // SEMNAV_SWEEP_ONLY=<key prefix> replays one failure (or one method) alone.
        if (const char* only = std::getenv("SEMNAV_SWEEP_ONLY");
            only != nullptr && !absl::StartsWith(key, only)) {
          continue;
        }
        ++calls;
        std::vector<std::string> problems;
        const std::vector<uint64_t> revisions_before = MapRevisions();
        last_map_numbers_.clear();

        const CallOutcome outcome =
            CallRaw(channel_, path, request.preamble, request.bytes, may_stay_open);
        const grpc::Status& status = outcome.status;
        const std::string code_name =
            absl::StatusCodeToString(static_cast<absl::StatusCode>(status.error_code()));

        const std::optional<common::v1::ErrorInfo> status_info =
            GetDetail<common::v1::ErrorInfo>(status);
        if (!outcome.finished_in_time) problems.push_back("the call did not end in time");
        // A server's own DEADLINE_EXCEEDED (a plan timeout) carries an ErrorInfo; the call's
        // deadline expiring does not.
        if (status.error_code() == grpc::StatusCode::INTERNAL ||
            status.error_code() == grpc::StatusCode::UNKNOWN ||
            status.error_code() == grpc::StatusCode::UNIMPLEMENTED ||
            (status.error_code() == grpc::StatusCode::DEADLINE_EXCEEDED && !status_info) ||
            (status.error_code() == grpc::StatusCode::CANCELLED && !outcome.cancelled_by_test)) {
          problems.push_back(absl::StrCat("status ", code_name));
        } else if (!status.ok() && !outcome.cancelled_by_test && !status_info) {
          problems.push_back("an error without ErrorInfo");
        }
        if (status.error_message().size() > kMaxMessageBytes) {
          problems.push_back(absl::StrCat("message of ", status.error_message().size(), " bytes"));
        }
        std::vector<common::v1::ErrorInfo> errors;
        bool rejected = !status.ok() && !outcome.cancelled_by_test;
        if (status.error_code() == grpc::StatusCode::INVALID_ARGUMENT && status_info) {
          errors.push_back(*status_info);
        }
        // A bidi stream may reject a message in-band, in its answer's ErrorInfo.
        for (const std::string& bytes : outcome.responses) {
          std::unique_ptr<Message> response = NewMessage(method->output_type());
          if (!response->ParseFromString(bytes)) {
            problems.push_back("a response does not parse");
            continue;
          }
          std::vector<common::v1::ErrorInfo> in_band;
          FindErrorInfos(*response, in_band);
          for (const common::v1::ErrorInfo& info : in_band) {
            if (info.reason().empty() && info.field().empty()) continue;
            rejected = true;
            errors.push_back(info);
            for (const auto& [name, value] : info.metadata()) {
              if (value.size() > kMaxMessageBytes) {
                problems.push_back(absl::StrCat("in-band ", name, " of ", value.size(), " bytes"));
              }
            }
          }
          std::vector<std::string> implausible;
          FindImplausibleNumbers(*response, "", implausible);
          if (!implausible.empty()) {
            problems.push_back(absl::StrCat("the answer holds ", implausible.front()));
          }
        }
        if (!request.field.empty() && rejected) {
          for (const common::v1::ErrorInfo& info : errors) {
            if (info.field().empty()) {
              problems.push_back(absl::StrCat("error (", info.reason(), ") names no field"));
            } else if (base_accepted && !NamesMutatedField(info.field(), request)) {
              // The unmutated request passes, so the mutation is what was wrong.
              problems.push_back(absl::StrCat("the error names '", info.field().substr(0, 80),
                                              "', not the mutated field"));
            }
          }
        }
        if (request.must_be_rejected && !rejected) {
          problems.push_back(outcome.cancelled_by_test ? "accepted (the stream stayed open)"
                                                       : "accepted");
        }
        if (request.is_base) {
          base_accepted = !rejected;
          // Mutations of a rejected base prove little; the summary lists these methods.
          if (!base_accepted) {
            std::string why = status.error_message().substr(0, 100);
            if (!errors.empty()) {
              const auto& metadata = errors.front().metadata();
              why = absl::StrCat(errors.front().field(), " ", errors.front().reason(), " ",
                                 metadata.contains("message") ? metadata.at("message") : "");
            }
            rejected_bases.push_back(absl::StrCat(key, " (", code_name, ": ", why, ")"));
          }
        }
        if (!request.parses && single_request) {
          if (status.error_code() != grpc::StatusCode::INVALID_ARGUMENT ||
              !absl::StrContains(status.error_message(), "could not be parsed")) {
            problems.push_back(absl::StrCat("an unparsable body got ", code_name, " '",
                                            status.error_message().substr(0, 80), "'"));
          }
        }

        // Work a call started (a frame being integrated) may still be running: give it a moment.
        if (!status.ok() || may_stay_open || !single_request) {
          absl::SleepFor(absl::Milliseconds(20));
        }
        const std::string ended = HowProcessEnded(process_->pid());
        const bool alive = ended.empty();
        if (!alive) {
          problems.push_back(absl::StrCat("the server ", ended));
        } else if (absl::Status serving = WaitForServing(channel_, "", absl::Seconds(3));
                   !serving.ok()) {
          problems.push_back(absl::StrCat("health: ", serving.message()));
        } else {
          const std::vector<uint64_t> revisions_after = MapRevisions();
          if (rejected && revisions_after != revisions_before) {
            problems.push_back(absl::StrCat("rejected (", code_name, ") but the map changed"));
          }
          if (!last_map_numbers_.empty()) {
            problems.push_back(absl::StrCat("the map now holds ", last_map_numbers_));
          }
        }
        if (!problems.empty()) {
          failures[key] = absl::StrCat(absl::StrJoin(problems, "; "), " [", code_name, ": ",
                                       status.error_message().substr(0, 160), "]");
        }
        if (!alive) {
          StartService();  // keep sweeping; the crash is recorded
          ASSERT_NE(process_, nullptr);
        }
      }
    }
  }

  auto allowed = [](const std::string& key) {
    for (const std::string& pending : kPendingFixes) {
      if (absl::StartsWith(key, pending)) return true;
    }
    return false;
  };
  std::vector<std::string> unexpected;
  for (const auto& [key, problem] : failures) {
    if (!allowed(key)) unexpected.push_back(absl::StrCat(key, ": ", problem));
  }
  for (const std::string& pending : kPendingFixes) {
    bool still_failing = false;
    for (const auto& [key, problem] : failures) still_failing |= absl::StartsWith(key, pending);
    bool this_binary = false;
    for (const std::string& service : GetParam().services) {
      this_binary |= absl::StartsWith(pending, service + "/");
    }
    if (this_binary && !still_failing) {
      std::cout << "kPendingFixes entry passes now, remove it: " << pending << "\n";
    }
  }
  std::cout << GetParam().binary << ": " << methods_swept.size() << " methods, " << calls
            << " calls, " << failures.size() << " failing (" << unexpected.size()
            << " not allow-listed) in " << absl::FormatDuration(absl::Now() - started) << "\n"
            << "bases rejected (their mutations are checked less):\n  "
            << absl::StrJoin(rejected_bases, "\n  ") << "\n";
  EXPECT_TRUE(unexpected.empty()) << unexpected.size() << " failures:\n"
                                  << absl::StrJoin(unexpected, "\n");
}

INSTANTIATE_TEST_SUITE_P(AllServices, RequestSweepTest, ::testing::ValuesIn(SweptBinaries()),
                         [](const ::testing::TestParamInfo<SweptBinary>& info) {
                           std::string name = info.param.binary;
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace semnav::testing
