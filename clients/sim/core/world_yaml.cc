#include "clients/sim/core/world_yaml.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/geometry2d.h"
#include "clients/sim/core/label_lexicon.h"
#include "clients/sim/core/robot_config.h"
#include "clients/sim/core/shape_queries.h"
#include "services/common/config/config_reader.h"
#include "services/common/status/field_error.h"

namespace semnav::sim {
namespace {

#define SIM_ASSIGN_OR_RETURN(lhs, expr)         \
  auto lhs##_or = (expr);                       \
  if (!lhs##_or.ok()) return lhs##_or.status(); \
  auto lhs = *std::move(lhs##_or)

#define SIM_RETURN_IF_ERROR(expr) \
  if (absl::Status s_ = (expr); !s_.ok()) return s_

absl::Status Invalid(const std::string& field, absl::string_view what) {
  return InvalidField(field, what);
}

// "objects[2].id": a field of a list item, for the checks made after reading.
std::string ItemField(absl::string_view list, size_t i, absl::string_view field) {
  return absl::StrCat(list, "[", i, "].", field);
}

// Geometry may reach this far past the bounds (rounding of written coordinates).
constexpr double kBoundsTolerance = 1e-3;

// A world file is data: a key written without a value is a slip, not "use the default".
ConfigReaderOptions WorldDocument() { return {.name = "world", .null_is_absent = false}; }

// ConfigReader reads any number yaml-cpp does, ".inf" and ".nan" too; world numbers are finite.
void CheckFiniteNumber(ConfigReader& r, absl::string_view key, double value) {
  r.Check(std::isfinite(value), key, "expected a finite number");
}

// An optional [r, g, b] (0-255) at `key`; *colour keeps its default when absent.
void ReadColour(ConfigReader& r, absl::string_view key, Rgb* colour) {
  Eigen::Vector3d v(colour->r, colour->g, colour->b);
  r.Read(key, &v);
  const bool in_range = (v.array() >= 0.0).all() && (v.array() <= 255.0).all();
  r.Check(in_range, key, "values must be 0-255");
  if (in_range) {
    *colour =
        Rgb{static_cast<uint8_t>(v[0]), static_cast<uint8_t>(v[1]), static_cast<uint8_t>(v[2])};
  }
}

// A required polygon of at least 3 [x, y] points at `key`.
std::vector<Eigen::Vector2d> ReadPolygon(ConfigReader& r, absl::string_view key) {
  std::vector<Eigen::Vector2d> polygon;
  r.Require(key, &polygon);
  r.Check(polygon.size() >= 3, key, "expected a list of at least 3 [x, y] points");
  return polygon;
}

BoxShape ReadBox(ConfigReader r) {
  BoxShape box;
  r.Require("center", &box.center).Require("size", &box.size);
  r.Read("yaw", &box.yaw).Read("base_z", &box.base_z);
  CheckFiniteNumber(r, "yaw", box.yaw);
  CheckFiniteNumber(r, "base_z", box.base_z);
  r.Check((box.size.array() > 0.0).all(), "size", "must be positive");
  return box;
}

PrismShape ReadPrism(ConfigReader r) {
  PrismShape prism;
  prism.polygon = ReadPolygon(r, "polygon");
  r.Read("base_z", &prism.base_z).Require("height", &prism.height);
  CheckFiniteNumber(r, "base_z", prism.base_z);
  CheckFiniteNumber(r, "height", prism.height);
  r.Check(prism.height > 0.0, "height", "must be positive");
  return prism;
}

Obstacle ReadObstacle(ConfigReader& r) {
  Obstacle obstacle;
  r.Require("kind", &obstacle.kind);
  ReadColour(r, "colour", &obstacle.colour);
  const bool box = r.Has("box"), prism = r.Has("prism");
  r.Check(box || prism, "box", "missing: an obstacle needs a box or a prism");
  r.Check(!(box && prism), "prism", "give either box or prism, not both");
  if (box) obstacle.shape = ReadBox(r.Child("box"));
  // Read even next to a box, so its own errors are named too.
  if (prism) {
    PrismShape shape = ReadPrism(r.Child("prism"));
    if (!box) obstacle.shape = std::move(shape);
  }
  return obstacle;
}

ObjectInstance ReadObject(ConfigReader& r) {
  ObjectInstance object;
  r.Require("id", &object.id).Require("label", &object.label).Read("room", &object.room);
  ReadColour(r, "colour", &object.colour);
  object.box = ReadBox(r.RequireChild("box"));
  r.Check(!object.id.empty(), "id", "must not be empty");
  r.Check(!object.label.empty(), "label", "must not be empty");
  return object;
}

Room ReadRoom(ConfigReader& r) {
  Room room;
  r.Require("name", &room.name).Require("type", &room.type);
  room.polygon = ReadPolygon(r, "polygon");
  r.Check(!room.name.empty(), "name", "must not be empty");
  return room;
}

StartPose ReadStart(ConfigReader& r) {
  StartPose start;
  std::string modality;
  r.Require("position", &start.position).Read("yaw", &start.yaw).Require("modality", &modality);
  CheckFiniteNumber(r, "yaw", start.yaw);
  const std::optional<Modality> parsed = ParseModality(modality);
  r.Check(parsed.has_value(), "modality", "expected ground, uav or fly_roll");
  if (parsed) start.modality = *parsed;
  return start;
}

// The items of the list at `key`, each read with `read`.
template <typename T, typename ReadFn>
std::vector<T> ReadList(ConfigReader& r, absl::string_view key, ReadFn read) {
  std::vector<T> list;
  for (ConfigReader& item : r.Items(key)) list.push_back(read(item));
  return list;
}

// Every field of the file; format errors are left in `r` for its Finish().
World ReadWorld(ConfigReader& r) {
  World world;
  r.Require("name", &world.name).Read("description", &world.description);
  r.Read("ceiling_height", &world.ceiling_height);
  r.Check(!world.name.empty(), "name", "must not be empty");
  CheckFiniteNumber(r, "ceiling_height", world.ceiling_height);
  r.Check(world.ceiling_height >= 0.0, "ceiling_height", "must be >= 0 (0 = open sky)");
  ConfigReader bounds = r.RequireChild("bounds");
  bounds.Require("min", &world.bounds_min).Require("max", &world.bounds_max);
  bounds.Check((world.bounds_max.array() > world.bounds_min.array()).all(), "max",
               "must exceed bounds.min");
  ReadColour(r, "floor_colour", &world.floor_colour);
  world.obstacles = ReadList<Obstacle>(r, "obstacles", ReadObstacle);
  world.objects = ReadList<ObjectInstance>(r, "objects", ReadObject);
  world.rooms = ReadList<Room>(r, "rooms", ReadRoom);
  world.starts = ReadList<StartPose>(r, "starts", ReadStart);
  return world;
}

absl::Status CheckReferences(const World& world) {
  std::set<std::string> rooms;
  for (size_t i = 0; i < world.rooms.size(); ++i) {
    if (!rooms.insert(world.rooms[i].name).second) {
      return Invalid(ItemField("rooms", i, "name"), "duplicate room name");
    }
  }
  std::set<std::string> ids;
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const ObjectInstance& object = world.objects[i];
    if (!ids.insert(object.id).second) {
      return Invalid(ItemField("objects", i, "id"), "duplicate object id");
    }
    if (!object.room.empty() && !rooms.contains(object.room)) {
      return Invalid(ItemField("objects", i, "room"), "names no room in rooms");
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
      return Invalid(ItemField("objects", i, "label"),
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
      return Invalid(ItemField("obstacles", i, box ? "box" : "prism.polygon"), inside);
    }
  }
  for (size_t i = 0; i < world.objects.size(); ++i) {
    const auto [lo, hi] = FootprintBounds(Shape(world.objects[i].box));
    if (!WithinBounds(world, lo, hi)) return Invalid(ItemField("objects", i, "box"), inside);
  }
  for (size_t i = 0; i < world.rooms.size(); ++i) {
    for (const Eigen::Vector2d& p : world.rooms[i].polygon) {
      if (!WithinBounds(world, p, p)) return Invalid(ItemField("rooms", i, "polygon"), inside);
    }
  }
  for (size_t i = 0; i < world.starts.size(); ++i) {
    const Eigen::Vector2d p = world.starts[i].position.head<2>();
    if (!WithinBounds(world, p, p)) return Invalid(ItemField("starts", i, "position"), inside);
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
        return Invalid(ItemField("starts", i, "position"),
                       absl::StrCat("the robot's body there touches obstacles[", k, "] (",
                                    world.obstacles[k].kind, ")"));
      }
    }
    for (size_t k = 0; k < world.objects.size(); ++k) {
      if (touches(Shape(world.objects[k].box))) {
        return Invalid(ItemField("starts", i, "position"),
                       absl::StrCat("the robot's body there touches objects[", k, "] (",
                                    world.objects[k].id, ")"));
      }
    }
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<World> ParseWorldYaml(const std::string& text) {
  SIM_ASSIGN_OR_RETURN(reader, ConfigReader::FromString(text, WorldDocument()));
  const World world = ReadWorld(reader);
  SIM_RETURN_IF_ERROR(reader.Finish());
  SIM_RETURN_IF_ERROR(CheckReferences(world));
  SIM_RETURN_IF_ERROR(CheckLabels(world));
  SIM_RETURN_IF_ERROR(CheckBounds(world));
  SIM_RETURN_IF_ERROR(CheckStarts(world));
  return world;
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
