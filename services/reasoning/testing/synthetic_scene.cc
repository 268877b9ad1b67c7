#include "services/reasoning/testing/synthetic_scene.h"

#include <array>
#include <string>

namespace semnav::reasoning::testing {
namespace {

constexpr std::array<const char*, 16> kLabels = {
    "chair",  "couch", "dining table", "tv",   "bed",   "potted plant", "bottle",  "cup", "book",
    "laptop", "sink",  "refrigerator", "oven", "clock", "vase",         "backpack"};

std::vector<float> Embedding(int dims, int64_t seed) {
  std::vector<float> out(static_cast<std::size_t>(dims));
  for (int i = 0; i < dims; ++i)
    out[static_cast<std::size_t>(i)] = static_cast<float>(((seed * 31 + i * 17) % 97) - 48);
  return out;
}

}  // namespace

SceneGraph SyntheticScene(int regions, int per_region, int embedding_dims) {
  SceneGraph graph;
  graph.revision = 1;
  int64_t next_id = 1;
  for (int r = 0; r < regions; ++r) {
    SceneRegion region{r, "area_" + std::to_string(r), {}};
    for (int k = 0; k < per_region; ++k) {
      SceneObject object;
      object.id = next_id++;
      object.label = kLabels[static_cast<std::size_t>((r * per_region + k) % kLabels.size())];
      object.position = Eigen::Vector3d(4.0 * r + 0.3 * k, 0.5 * k, 0.4);
      object.score = 0.5 + 0.04 * (k % 10);
      object.detection_count = 1 + k % 12;
      object.region_id = r;
      object.embedding = Embedding(embedding_dims, object.id);
      if (k > 0) graph.relations.push_back({object.id, "near", object.id - 1, 0.3 + 0.01 * k});
      region.object_ids.push_back(object.id);
      graph.objects.push_back(std::move(object));
    }
    graph.regions.push_back(std::move(region));
  }
  const int middle = regions / 2;
  SceneObject target;
  target.id = kSyntheticTargetId;
  target.label = "fire extinguisher";
  target.attributes = {"red"};
  target.position = Eigen::Vector3d(4.0 * middle + 1.0, 2.0, 0.5);
  target.score = 0.85;
  target.detection_count = 15;
  target.region_id = middle;
  target.embedding = Embedding(embedding_dims, target.id);
  SceneObject door = target;
  door.id = kSyntheticDoorId;
  door.label = "door";
  door.attributes.clear();
  door.position.x() += 0.8;
  door.embedding = Embedding(embedding_dims, door.id);
  graph.relations.push_back({target.id, "near", door.id, 0.8});
  graph.regions[static_cast<std::size_t>(middle)].object_ids.push_back(target.id);
  graph.regions[static_cast<std::size_t>(middle)].object_ids.push_back(door.id);
  graph.objects.push_back(std::move(target));
  graph.objects.push_back(std::move(door));
  return graph;
}

}  // namespace semnav::reasoning::testing
