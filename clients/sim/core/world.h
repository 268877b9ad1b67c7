#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

// The simulated world as plain values: what a world file describes (docs/simulation.md).
// Frame: x east, y north, z up, metres; yaw in radians counter-clockwise from +x.
namespace semnav::sim {

struct Rgb {
  uint8_t r = 128, g = 128, b = 128;
  bool operator==(const Rgb&) const = default;
};

// An upright box turned by yaw about z. `center` is the footprint centre, `base_z` the
// bottom face height, `size` = (length along yaw, width, height).
struct BoxShape {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();
  double yaw = 0.0;
  Eigen::Vector3d size = Eigen::Vector3d::Ones();
  double base_z = 0.0;
  double top_z() const { return base_z + size.z(); }
};

// A simple polygon (either winding, not closed) extruded from base_z up by height.
struct PrismShape {
  std::vector<Eigen::Vector2d> polygon;
  double base_z = 0.0;
  double height = 1.0;
  double top_z() const { return base_z + height; }
};

using Shape = std::variant<BoxShape, PrismShape>;

// Unlabelled static geometry. `kind` is free text (wall, furniture, tree, building, ...);
// "wall" and "building" are structure the fly-roll robot can never fly over.
struct Obstacle {
  std::string kind;
  Rgb colour;
  Shape shape;
};

// A labelled object the robot may be asked to find; it is solid like an obstacle.
struct ObjectInstance {
  std::string id;     // unique in the world
  std::string label;  // English class name, lower case ("chair", "potted plant")
  Rgb colour;
  BoxShape box;
  std::string room;  // Room::name or empty
};

struct Room {
  std::string name;  // unique in the world
  std::string type;  // bedroom, kitchen, office, ...
  std::vector<Eigen::Vector2d> polygon;
};

enum class Modality { kGround, kUav, kFlyRoll };
std::string_view ModalityName(Modality modality);
std::optional<Modality> ParseModality(std::string_view name);

struct StartPose {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double yaw = 0.0;
  Modality modality = Modality::kGround;
};

struct World {
  std::string name;
  std::string description;
  Eigen::Vector2d bounds_min = Eigen::Vector2d::Zero();
  Eigen::Vector2d bounds_max = Eigen::Vector2d::Zero();
  double ceiling_height = 0.0;  // 0: open sky (no ceiling plane)
  Rgb floor_colour{150, 150, 150};
  std::vector<Obstacle> obstacles;
  std::vector<ObjectInstance> objects;
  std::vector<Room> rooms;
  std::vector<StartPose> starts;
};

// Height of the top face of a shape.
double ShapeTop(const Shape& shape);

// Obstacle kinds that are building structure ("wall", "building"): nothing is reached or seen
// through them, and the fly-roll robot never flies over them.
bool IsStructure(std::string_view kind);

}  // namespace semnav::sim
