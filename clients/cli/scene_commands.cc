// scene show: the mapping service's scene graph as tables.
#include <map>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "clients/cli/call.h"
#include "clients/cli/command.h"
#include "clients/cli/core/table.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"

namespace semnav::cli {
namespace {

namespace api = ::semnav::mapping::v1;

std::string Metres(double value) { return FormatFixed(value, 2); }

std::string RenderGraph(const api::SceneGraph& graph) {
  std::string out = absl::StrCat("scene graph revision ", graph.revision(), ": ",
                                 graph.objects_size(), " objects, ", graph.relations_size(),
                                 " relations, ", graph.regions_size(), " regions\n");
  if (!graph.summary().empty()) absl::StrAppend(&out, graph.summary(), "\n");
  std::map<uint64_t, std::string> labels;
  Table objects(
      {"ID", "LABEL", "X", "Y", "Z", "SIZE_X", "SIZE_Y", "SIZE_Z", "SCORE", "SEEN", "REGION"});
  for (const api::SceneObject& object : graph.objects()) {
    labels[object.id()] = object.label();
    objects.AddRow({std::to_string(object.id()), object.label(), Metres(object.position().x()),
                    Metres(object.position().y()), Metres(object.position().z()),
                    Metres(object.size().x()), Metres(object.size().y()), Metres(object.size().z()),
                    FormatFixed(object.score(), 2), std::to_string(object.observation_count()),
                    object.region_id() < 0 ? "" : std::to_string(object.region_id())});
  }
  if (!objects.empty()) absl::StrAppend(&out, "\n", objects.Render());
  Table relations({"SUBJECT", "RELATION", "OBJECT", "DISTANCE"});
  for (const api::Relation& relation : graph.relations()) {
    relations.AddRow({absl::StrCat(relation.subject_id(), " ", labels[relation.subject_id()]),
                      ShortEnumName(api::RelationKind_Name(relation.kind()), "RELATION_KIND_"),
                      absl::StrCat(relation.object_id(), " ", labels[relation.object_id()]),
                      Metres(relation.distance())});
  }
  if (!relations.empty()) absl::StrAppend(&out, "\n", relations.Render());
  Table regions({"REGION", "NAME", "CENTRE_X", "CENTRE_Y", "OBJECTS"});
  for (const api::Region& region : graph.regions()) {
    regions.AddRow({std::to_string(region.id()), region.name(), Metres(region.centre().x()),
                    Metres(region.centre().y()), absl::StrJoin(region.object_ids(), " ")});
  }
  if (!regions.empty()) absl::StrAppend(&out, "\n", regions.Render());
  return out;
}

int Show(const Invocation& invocation) {
  return RunUnary<api::MappingService>(
      invocation, Service::kMapping, &api::MappingService::Stub::GetSceneGraph,
      api::GetSceneGraphRequest(),
      [](const api::GetSceneGraphResponse& r) { return RenderGraph(r.graph()); });
}

}  // namespace

std::vector<Command> SceneCommands() {
  return {
      {"scene",
       "show",
       "",
       "the scene graph: objects, relations and regions as tables",
       Service::kMapping,
       {},
       Show,
       0},
  };
}

}  // namespace semnav::cli
