#include "services/reasoning/core/scene_graph_json.h"

#include <cmath>

#include "nlohmann/json.hpp"

namespace semnav::reasoning {
namespace {

double Round2(double value) { return std::round(value * 100.0) / 100.0; }

}  // namespace

std::string SceneGraphToPromptJson(const SceneGraph& graph) {
  nlohmann::json objects = nlohmann::json::array();
  for (const SceneObject& object : graph.objects) {
    nlohmann::json item = {
        {"id", object.id},
        {"label", object.label},
        {"position",
         {Round2(object.position.x()), Round2(object.position.y()), Round2(object.position.z())}},
        {"score", Round2(object.score)},
        {"detections", object.detection_count}};
    if (!object.attributes.empty()) item["attributes"] = object.attributes;
    if (object.region_id >= 0) item["region"] = object.region_id;
    objects.push_back(std::move(item));
  }
  nlohmann::json relations = nlohmann::json::array();
  for (const SceneRelation& relation : graph.relations) {
    relations.push_back({relation.subject_id, relation.relation, relation.object_id});
  }
  nlohmann::json regions = nlohmann::json::array();
  for (const SceneRegion& region : graph.regions) {
    regions.push_back({{"id", region.id}, {"name", region.name}, {"objects", region.object_ids}});
  }
  return nlohmann::json{{"objects", objects}, {"relations", relations}, {"regions", regions}}
      .dump();
}

int EstimateTokens(const std::string& text) { return static_cast<int>((text.size() + 3) / 4); }

}  // namespace semnav::reasoning
