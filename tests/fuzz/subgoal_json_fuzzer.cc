// The gateway's decoders of model answers (services/reasoning/core): the decomposition's subgoal
// list (subgoal_json) and the slow path's match_target answer (slow_answer), against a small
// scene graph.
#include <cstdint>
#include <cstdlib>

#include "services/reasoning/core/slow_answer.h"
#include "services/reasoning/core/subgoal_json.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

semnav::reasoning::SceneGraph SmallGraph() {
  semnav::reasoning::SceneGraph graph;
  graph.revision = 3;
  graph.objects.resize(2);
  graph.objects[0].id = 1;
  graph.objects[0].label = "chair";
  graph.objects[1].id = 2;
  graph.objects[1].label = "red cup";
  graph.objects[1].position = {1.0, 2.0, 0.5};
  graph.relations.push_back({2, "near", 1, 0.8});
  graph.regions.push_back({7, "kitchen", {1, 2}});
  return graph;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace semnav::reasoning;
  static const SceneGraph graph = SmallGraph();
  const std::string text = semnav::fuzz::AsString(data, size);
  absl::StatusOr<std::vector<Subgoal>> subgoals = ParseModelSubgoals(text);
  if (subgoals.ok() && (subgoals->empty() || subgoals->size() > kMaxModelSubgoals)) std::abort();
  absl::StatusOr<SlowDecision> decision = ParseResolveAnswer(text, graph, SlowPathConfig());
  if (decision.ok() && decision->action != SlowAction::kExplore &&
      graph.FindObject(decision->object_id) == nullptr) {
    std::abort();  // a goal must be one of the graph's objects
  }
  return 0;
}
