// WorldToYaml: the writer half of world_yaml.h, emitting the same fields the parser reads.
#include <yaml-cpp/yaml.h>

#include <cmath>

#include "clients/sim/core/world_yaml.h"

namespace semnav::sim {
namespace {

// Millimetre precision keeps files small and diffs readable.
double Round(double v) {
  const double r = std::round(v * 1000.0) / 1000.0;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

void EmitNumbers(YAML::Emitter& out, std::initializer_list<double> values) {
  out << YAML::Flow << YAML::BeginSeq;
  for (double v : values) out << Round(v);
  out << YAML::EndSeq;
}

void EmitColour(YAML::Emitter& out, const Rgb& c) {
  out << YAML::Flow << YAML::BeginSeq << static_cast<int>(c.r) << static_cast<int>(c.g)
      << static_cast<int>(c.b) << YAML::EndSeq;
}

void EmitPolygon(YAML::Emitter& out, const std::vector<Eigen::Vector2d>& polygon) {
  out << YAML::Flow << YAML::BeginSeq;
  for (const auto& p : polygon) EmitNumbers(out, {p.x(), p.y()});
  out << YAML::EndSeq;
}

void EmitBox(YAML::Emitter& out, const BoxShape& box) {
  out << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "center";
  EmitNumbers(out, {box.center.x(), box.center.y()});
  out << YAML::Key << "size";
  EmitNumbers(out, {box.size.x(), box.size.y(), box.size.z()});
  if (box.yaw != 0.0) out << YAML::Key << "yaw" << Round(box.yaw);
  if (box.base_z != 0.0) out << YAML::Key << "base_z" << Round(box.base_z);
  out << YAML::EndMap;
}

void EmitPrism(YAML::Emitter& out, const PrismShape& prism) {
  out << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "polygon";
  EmitPolygon(out, prism.polygon);
  if (prism.base_z != 0.0) out << YAML::Key << "base_z" << Round(prism.base_z);
  out << YAML::Key << "height" << Round(prism.height);
  out << YAML::EndMap;
}

void EmitObstacle(YAML::Emitter& out, const Obstacle& obstacle) {
  out << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << obstacle.kind;
  out << YAML::Key << "colour";
  EmitColour(out, obstacle.colour);
  if (const auto* box = std::get_if<BoxShape>(&obstacle.shape)) {
    out << YAML::Key << "box";
    EmitBox(out, *box);
  } else {
    out << YAML::Key << "prism";
    EmitPrism(out, std::get<PrismShape>(obstacle.shape));
  }
  out << YAML::EndMap;
}

void EmitObject(YAML::Emitter& out, const ObjectInstance& object) {
  out << YAML::BeginMap << YAML::Key << "id" << YAML::Value << object.id;
  out << YAML::Key << "label" << YAML::Value << object.label;
  out << YAML::Key << "colour";
  EmitColour(out, object.colour);
  if (!object.room.empty()) out << YAML::Key << "room" << YAML::Value << object.room;
  out << YAML::Key << "box";
  EmitBox(out, object.box);
  out << YAML::EndMap;
}

}  // namespace

std::string WorldToYaml(const World& world) {
  YAML::Emitter out;
  out.SetDoublePrecision(
      15);  // a value rounded to 1 mm prints as such ("28.95", not "28.949999999999999")
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << world.name;
  if (!world.description.empty()) {
    out << YAML::Key << "description" << YAML::Value << world.description;
  }
  out << YAML::Key << "bounds" << YAML::Value << YAML::Flow << YAML::BeginMap;
  out << YAML::Key << "min";
  EmitNumbers(out, {world.bounds_min.x(), world.bounds_min.y()});
  out << YAML::Key << "max";
  EmitNumbers(out, {world.bounds_max.x(), world.bounds_max.y()});
  out << YAML::EndMap;
  if (world.ceiling_height > 0.0) {
    out << YAML::Key << "ceiling_height" << YAML::Value << Round(world.ceiling_height);
  }
  out << YAML::Key << "floor_colour";
  EmitColour(out, world.floor_colour);
  out << YAML::Key << "rooms" << YAML::Value << YAML::BeginSeq;
  for (const Room& room : world.rooms) {
    out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << room.name;
    out << YAML::Key << "type" << YAML::Value << room.type << YAML::Key << "polygon";
    EmitPolygon(out, room.polygon);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "starts" << YAML::Value << YAML::BeginSeq;
  for (const StartPose& start : world.starts) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "position";
    EmitNumbers(out, {start.position.x(), start.position.y(), start.position.z()});
    out << YAML::Key << "yaw" << Round(start.yaw);
    out << YAML::Key << "modality" << std::string(ModalityName(start.modality));
    out << YAML::EndMap;
  }
  out << YAML::EndSeq;
  out << YAML::Key << "objects" << YAML::Value << YAML::BeginSeq;
  for (const ObjectInstance& object : world.objects) EmitObject(out, object);
  out << YAML::EndSeq;
  out << YAML::Key << "obstacles" << YAML::Value << YAML::BeginSeq;
  for (const Obstacle& obstacle : world.obstacles) EmitObstacle(out, obstacle);
  out << YAML::EndSeq;
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

}  // namespace semnav::sim
