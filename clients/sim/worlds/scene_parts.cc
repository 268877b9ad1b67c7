#include "clients/sim/worlds/scene_parts.h"

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "clients/sim/core/geometry2d.h"

namespace semnav::sim::parts {

BoxShape Box(double x, double y, double length, double width, double height, double yaw,
             double base_z) {
  BoxShape box;
  box.center = Eigen::Vector2d(x, y);
  box.size = Eigen::Vector3d(length, width, height);
  box.yaw = yaw;
  box.base_z = base_z;
  return box;
}

Obstacle Surface(const std::string& kind, Rgb colour, double x0, double y0, double x1, double y1) {
  return Obstacle{kind, colour, PrismShape{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, 0.0, 0.02}};
}

void AddTree(World& world, double x, double y, double height) {
  world.obstacles.push_back(Obstacle{"tree", Rgb{100, 70, 40}, Box(x, y, 0.35, 0.35, 2.0)});
  world.obstacles.push_back(
      Obstacle{"tree", Rgb{50, 120, 50}, Box(x, y, 2.4, 2.4, height - 2.0, 0.3, 2.0)});
}

void AddObject(World& world, const std::string& label, Rgb colour, const BoxShape& box,
               const std::string& room) {
  int n = 1;
  for (const ObjectInstance& o : world.objects) n += o.label == label ? 1 : 0;
  world.objects.push_back(ObjectInstance{
      absl::StrCat(absl::StrReplaceAll(label, {{" ", "_"}}), "_", n), label, colour, box, room});
}

bool FreeSpot(const World& world, const BoxShape& box, double gap) {
  for (const ObjectInstance& o : world.objects) {
    if (FootprintsOverlap(box, o.box, gap / 2)) return false;
  }
  for (const Obstacle& o : world.obstacles) {
    const auto* other = std::get_if<BoxShape>(&o.shape);
    if (other != nullptr && FootprintsOverlap(box, *other, gap / 2)) return false;
    if (const auto* prism = std::get_if<PrismShape>(&o.shape); prism && prism->height > 0.1) {
      for (const auto& c : BoxCorners(box)) {
        if (PointInPolygon(prism->polygon, c)) return false;
      }
    }
  }
  return true;
}

}  // namespace semnav::sim::parts
