#include "clients/sim/core/world_yaml.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/label_lexicon.h"
#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/shape_queries.h"
#include "clients/sim/core/yaml_fields.h"
#include "services/common/status/field_error.h"

namespace semnav::sim {
namespace {

namespace yf = yaml_fields;

#define SIM_ASSIGN_OR_RETURN(lhs, expr)         \
  auto lhs##_or = (expr);                       \
  if (!lhs##_or.ok()) return lhs##_or.status(); \
  auto lhs = *std::move(lhs##_or)

#define SIM_RETURN_IF_ERROR(expr) \
  if (absl::Status s_ = (expr); !s_.ok()) return s_

absl::Status Invalid(const std::string& field, absl::string_view what) {
  return InvalidField(field, what);
}

// Geometry may reach this far past the bounds (rounding of written coordinates).
constexpr double kBoundsTolerance = 1e-3;

absl::StatusOr<Rgb> ReadColour(const YAML::Node& map, const std::string& path) {
  const YAML::Node node = map["colour"];
  if (!node) return Rgb{};
  SIM_ASSIGN_OR_RETURN(v, yf::ReadNumbers(node, yf::Join(path, "colour"), 3));
  for (int i = 0; i < 3; ++i) {
    if (v[i] < 0 || v[i] > 255) return Invalid(yf::Join(path, "colour"), "values must be 0-255");
  }
  return Rgb{static_cast<uint8_t>(v[0]), static_cast<uint8_t>(v[1]), static_cast<uint8_t>(v[2])};
}

absl::StatusOr<std::vector<Eigen::Vector2d>> ReadPolygon(const YAML::Node& node,
                                                         const std::string& path) {
  if (!node || !node.IsSequence() || node.size() < 3) {
    return Invalid(path, "expected a list of at least 3 [x, y] points");
  }
  std::vector<Eigen::Vector2d> polygon;
  for (size_t i = 0; i < node.size(); ++i) {
    SIM_ASSIGN_OR_RETURN(p, yf::ReadNumbers(node[i], yf::Index(path, i), 2));
    polygon.emplace_back(p[0], p[1]);
  }
  return polygon;
}

absl::StatusOr<BoxShape> ReadBox(const YAML::Node& node, const std::string& path) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(node, path));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(node, path, {"center", "size", "yaw", "base_z"}));
  BoxShape box;
  SIM_ASSIGN_OR_RETURN(center, yf::ReadNumbers(node["center"], yf::Join(path, "center"), 2));
  SIM_ASSIGN_OR_RETURN(size, yf::ReadNumbers(node["size"], yf::Join(path, "size"), 3));
  const double zero = 0.0;
  SIM_ASSIGN_OR_RETURN(yaw, yf::ReadDouble(node, path, "yaw", &zero));
  SIM_ASSIGN_OR_RETURN(base_z, yf::ReadDouble(node, path, "base_z", &zero));
  if ((size.array() <= 0.0).any()) return Invalid(yf::Join(path, "size"), "must be positive");
  box.center = center;
  box.size = size;
  box.yaw = yaw;
  box.base_z = base_z;
  return box;
}

absl::StatusOr<PrismShape> ReadPrism(const YAML::Node& node, const std::string& path) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(node, path));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(node, path, {"polygon", "base_z", "height"}));
  PrismShape prism;
  SIM_ASSIGN_OR_RETURN(polygon, ReadPolygon(node["polygon"], yf::Join(path, "polygon")));
  const double zero = 0.0;
  SIM_ASSIGN_OR_RETURN(base_z, yf::ReadDouble(node, path, "base_z", &zero));
  SIM_ASSIGN_OR_RETURN(height, yf::ReadDouble(node, path, "height"));
  if (height <= 0.0) return Invalid(yf::Join(path, "height"), "must be positive");
  prism.polygon = std::move(polygon);
  prism.base_z = base_z;
  prism.height = height;
  return prism;
}

absl::StatusOr<Obstacle> ReadObstacle(const YAML::Node& node, const std::string& path) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(node, path));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(node, path, {"kind", "colour", "box", "prism"}));
  Obstacle obstacle;
  SIM_ASSIGN_OR_RETURN(kind, yf::ReadString(node, path, "kind"));
  SIM_ASSIGN_OR_RETURN(colour, ReadColour(node, path));
  obstacle.kind = kind;
  obstacle.colour = colour;
  if (node["box"] && node["prism"]) return Invalid(path, "give either box or prism, not both");
  if (node["box"]) {
    SIM_ASSIGN_OR_RETURN(box, ReadBox(node["box"], yf::Join(path, "box")));
    obstacle.shape = box;
  } else if (node["prism"]) {
    SIM_ASSIGN_OR_RETURN(prism, ReadPrism(node["prism"], yf::Join(path, "prism")));
    obstacle.shape = prism;
  } else {
    return Invalid(path, "needs a box or a prism");
  }
  return obstacle;
}

absl::StatusOr<ObjectInstance> ReadObject(const YAML::Node& node, const std::string& path) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(node, path));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(node, path, {"id", "label", "colour", "box", "room"}));
  ObjectInstance object;
  const std::string empty;
  SIM_ASSIGN_OR_RETURN(id, yf::ReadString(node, path, "id"));
  SIM_ASSIGN_OR_RETURN(label, yf::ReadString(node, path, "label"));
  SIM_ASSIGN_OR_RETURN(room, yf::ReadString(node, path, "room", &empty));
  SIM_ASSIGN_OR_RETURN(colour, ReadColour(node, path));
  SIM_ASSIGN_OR_RETURN(box, ReadBox(node["box"], yf::Join(path, "box")));
  if (id.empty()) return Invalid(yf::Join(path, "id"), "must not be empty");
  if (label.empty()) return Invalid(yf::Join(path, "label"), "must not be empty");
  object.id = id;
  object.label = label;
  object.room = room;
  object.colour = colour;
  object.box = box;
  return object;
}

absl::StatusOr<Room> ReadRoom(const YAML::Node& node, const std::string& path) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(node, path));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(node, path, {"name", "type", "polygon"}));
  Room room;
  SIM_ASSIGN_OR_RETURN(name, yf::ReadString(node, path, "name"));
  SIM_ASSIGN_OR_RETURN(type, yf::ReadString(node, path, "type"));
  SIM_ASSIGN_OR_RETURN(polygon, ReadPolygon(node["polygon"], yf::Join(path, "polygon")));
  if (name.empty()) return Invalid(yf::Join(path, "name"), "must not be empty");
  room.name = name;
  room.type = type;
  room.polygon = std::move(polygon);
  return room;
}

absl::StatusOr<StartPose> ReadStart(const YAML::Node& node, const std::string& path) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(node, path));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(node, path, {"position", "yaw", "modality"}));
  StartPose start;
  SIM_ASSIGN_OR_RETURN(position, yf::ReadNumbers(node["position"], yf::Join(path, "position"), 3));
  const double zero = 0.0;
  SIM_ASSIGN_OR_RETURN(yaw, yf::ReadDouble(node, path, "yaw", &zero));
  SIM_ASSIGN_OR_RETURN(modality_name, yf::ReadString(node, path, "modality"));
  const std::optional<Modality> modality = ParseModality(modality_name);
  if (!modality) {
    return Invalid(yf::Join(path, "modality"), "expected ground, uav or fly_roll");
  }
  start.position = position;
  start.yaw = yaw;
  start.modality = *modality;
  return start;
}

// Reads the list at `key` element by element with `read`.
template <typename T, typename ReadFn>
absl::Status ReadList(const YAML::Node& root, const char* key, ReadFn read, std::vector<T>* out) {
  const YAML::Node list = root[key];
  if (!list) return absl::OkStatus();
  SIM_RETURN_IF_ERROR(yf::ExpectSequence(list, key));
  for (size_t i = 0; i < list.size(); ++i) {
    SIM_ASSIGN_OR_RETURN(item, read(list[i], yf::Index(key, i)));
    out->push_back(std::move(item));
  }
  return absl::OkStatus();
}

absl::Status CheckReferences(const World& world) {
  std::set<std::string> rooms;
  for (size_t i = 0; i < world.rooms.size(); ++i) {
    if (!rooms.insert(world.rooms[i].name).second) {
      return Invalid(yf::Index("rooms", i) + ".name", "duplicate room name");
    }
  }
  std::set<std::string> ids;
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const ObjectInstance& object = world.objects[i];
    if (!ids.insert(object.id).second) {
      return Invalid(yf::Index("objects", i) + ".id", "duplicate object id");
    }
    if (!object.room.empty() && !rooms.contains(object.room)) {
      return Invalid(yf::Index("objects", i) + ".room", "names no room in rooms");
    }
  }
  if (world.starts.empty()) return Invalid("starts", "at least one start pose is needed");
  return absl::OkStatus();
}

// Every object label must be an object the gateway can name (any English form of a lexicon
// object: "couch", "sofa", "table"): a target it cannot parse is no benchmark of search.
absl::Status CheckLabels(const World& world) {
  SIM_ASSIGN_OR_RETURN(lexicon, LabelLexicon());
  for (size_t i = 0; i < world.objects.size(); ++i) {
    if (lexicon->Find(world.objects[i].label, TermKind::kObject) == nullptr) {
      return Invalid(yf::Index("objects", i) + ".label",
                     absl::StrCat("\"", Preview(world.objects[i].label),
                                  "\" is not an object of the reasoning lexicon"));
    }
  }
  return absl::OkStatus();
}

bool WithinBounds(const World& world, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  return (lo.array() >= world.bounds_min.array() - kBoundsTolerance).all() &&
         (hi.array() <= world.bounds_max.array() + kBoundsTolerance).all();
}

// Obstacles, objects, rooms and starts lie inside the bounds: the grids, the maps and the
// search area cover the bounds and nothing else.
absl::Status CheckBounds(const World& world) {
  const std::string inside = "lies outside the bounds";
  for (size_t i = 0; i < world.obstacles.size(); ++i) {
    const auto [lo, hi] = FootprintBounds(world.obstacles[i].shape);
    if (!WithinBounds(world, lo, hi)) {
      const bool box = std::holds_alternative<BoxShape>(world.obstacles[i].shape);
      return Invalid(yf::Index("obstacles", i) + (box ? ".box" : ".prism.polygon"), inside);
    }
  }
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const auto [lo, hi] = FootprintBounds(Shape(world.objects[i].box));
    if (!WithinBounds(world, lo, hi)) return Invalid(yf::Index("objects", i) + ".box", inside);
  }
  for (size_t i = 0; i < world.rooms.size(); ++i) {
    for (const Eigen::Vector2d& p : world.rooms[i].polygon) {
      if (!WithinBounds(world, p, p)) return Invalid(yf::Index("rooms", i) + ".polygon", inside);
    }
  }
  for (size_t i = 0; i < world.starts.size(); ++i) {
    const Eigen::Vector2d p = world.starts[i].position.head<2>();
    if (!WithinBounds(world, p, p)) return Invalid(yf::Index("starts", i) + ".position", inside);
  }
  return absl::OkStatus();
}

// A start is where the robot's body (the upright cylinder of its modality, RobotConfig) stands:
// it must not touch a solid, or the robot is stuck or in collision before it moves.
absl::Status CheckStarts(const World& world) {
  for (size_t i = 0; i < world.starts.size(); ++i) {
    const StartPose& start = world.starts[i];
    const RobotConfig body = RobotConfig::ForModality(start.modality);
    const Eigen::Vector2d at = start.position.head<2>();
    const double z0 = start.position.z() + body.ground_clearance,
                 z1 = start.position.z() + body.body_height;
    auto touches = [&](const Shape& shape) {
      return CylinderOverlaps(shape, at, body.radius, z0, z1);
    };
    for (size_t k = 0; k < world.obstacles.size(); ++k) {
      if (touches(world.obstacles[k].shape)) {
        return Invalid(yf::Index("starts", i) + ".position",
                       absl::StrCat("the robot's body there touches obstacles[", k, "] (",
                                    world.obstacles[k].kind, ")"));
      }
    }
    for (size_t k = 0; k < world.objects.size(); ++k) {
      if (touches(Shape(world.objects[k].box))) {
        return Invalid(yf::Index("starts", i) + ".position",
                       absl::StrCat("the robot's body there touches objects[", k, "] (",
                                    world.objects[k].id, ")"));
      }
    }
  }
  return absl::OkStatus();
}

absl::StatusOr<World> ParseRoot(const YAML::Node& root) {
  SIM_RETURN_IF_ERROR(yf::ExpectMap(root, ""));
  SIM_RETURN_IF_ERROR(yf::CheckKeys(root, "",
                                    {"name", "description", "bounds", "ceiling_height",
                                     "floor_colour", "obstacles", "objects", "rooms", "starts"}));
  World world;
  const std::string empty;
  const double zero = 0.0;
  SIM_ASSIGN_OR_RETURN(name, yf::ReadString(root, "", "name"));
  SIM_ASSIGN_OR_RETURN(description, yf::ReadString(root, "", "description", &empty));
  SIM_ASSIGN_OR_RETURN(ceiling, yf::ReadDouble(root, "", "ceiling_height", &zero));
  if (name.empty()) return Invalid("name", "must not be empty");
  if (ceiling < 0.0) return Invalid("ceiling_height", "must be >= 0 (0 = open sky)");
  world.name = name;
  world.description = description;
  world.ceiling_height = ceiling;
  const YAML::Node bounds = root["bounds"];
  if (!bounds || !bounds.IsMap()) return Invalid("bounds", "expected {min: [x, y], max: [x, y]}");
  SIM_RETURN_IF_ERROR(yf::CheckKeys(bounds, "bounds", {"min", "max"}));
  SIM_ASSIGN_OR_RETURN(lo, yf::ReadNumbers(bounds["min"], "bounds.min", 2));
  SIM_ASSIGN_OR_RETURN(hi, yf::ReadNumbers(bounds["max"], "bounds.max", 2));
  if ((hi.array() <= lo.array()).any()) return Invalid("bounds.max", "must exceed bounds.min");
  world.bounds_min = lo;
  world.bounds_max = hi;
  if (root["floor_colour"]) {
    YAML::Node holder;
    holder["colour"] = root["floor_colour"];
    auto colour = ReadColour(holder, "");
    if (!colour.ok()) return Invalid("floor_colour", "expected [r, g, b] with values 0-255");
    world.floor_colour = *colour;
  }
  SIM_RETURN_IF_ERROR(ReadList(root, "obstacles", ReadObstacle, &world.obstacles));
  SIM_RETURN_IF_ERROR(ReadList(root, "objects", ReadObject, &world.objects));
  SIM_RETURN_IF_ERROR(ReadList(root, "rooms", ReadRoom, &world.rooms));
  SIM_RETURN_IF_ERROR(ReadList(root, "starts", ReadStart, &world.starts));
  SIM_RETURN_IF_ERROR(CheckReferences(world));
  SIM_RETURN_IF_ERROR(CheckLabels(world));
  SIM_RETURN_IF_ERROR(CheckBounds(world));
  SIM_RETURN_IF_ERROR(CheckStarts(world));
  return world;
}

}  // namespace

absl::StatusOr<World> ParseWorldYaml(const std::string& text) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return absl::InvalidArgumentError(absl::StrCat("world: YAML syntax error: ", e.what()));
  }
  return ParseRoot(root);
}

absl::StatusOr<World> LoadWorldFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat("world file not readable: ", path));
  std::stringstream text;
  text << in.rdbuf();
  absl::StatusOr<World> world = ParseWorldYaml(text.str());
  if (!world.ok()) {
    // The file name leads the message; the field payload stays.
    absl::Status named(world.status().code(), absl::StrCat(path, ": ", world.status().message()));
    world.status().ForEachPayload(
        [&](absl::string_view url, const absl::Cord& payload) { named.SetPayload(url, payload); });
    return named;
  }
  return world;
}

absl::StatusOr<std::vector<World>> LoadSuite(const std::string& directory) {
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error)) {
    return absl::NotFoundError(absl::StrCat("suite folder not found: ", directory));
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    if (entry.is_regular_file() && entry.path().extension() == ".yaml") {
      files.push_back(entry.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<World> worlds;
  for (const std::string& file : files) {
    SIM_ASSIGN_OR_RETURN(world, LoadWorldFile(file));
    worlds.push_back(std::move(world));
  }
  return worlds;
}

absl::Status SaveWorldFile(const World& world, const std::string& path) {
  std::ofstream out(path);
  out << WorldToYaml(world);
  out.close();
  if (!out) return absl::InternalError(absl::StrCat("could not write ", path));
  return absl::OkStatus();
}

}  // namespace semnav::sim
