#include "services/reasoning/core/exploration_context.h"

#include <map>

#include "gtest/gtest.h"
#include "services/reasoning/core/conceptnet_cooccurrence.h"
#include "services/reasoning/testing/test_lexicon.h"

namespace semnav::reasoning {
namespace {

// A prior with fixed pairs, so the context's terms can be checked by hand.
class TablePrior final : public CooccurrencePrior {
 public:
  explicit TablePrior(std::map<std::pair<std::string, std::string>, double> table)
      : table_(std::move(table)) {}
  double Cooccurrence(std::string_view target, std::string_view label) const override {
    auto it = table_.find({std::string(target), std::string(label)});
    return it == table_.end() ? 0.0 : it->second;
  }

 private:
  std::map<std::pair<std::string, std::string>, double> table_;
};

SceneObject Object(int64_t id, const char* label, double x) {
  SceneObject object;
  object.id = id;
  object.label = label;
  object.position = Eigen::Vector3d(x, 0.0, 0.0);
  return object;
}

class GatewayExplorationContextTest : public ::testing::Test {
 protected:
  LabelMatcher matcher_{&ShippedLexicon(), 0.5};
};

TEST_F(GatewayExplorationContextTest, RelevanceRelationAndCooccurrenceByHand) {
  SceneGraph graph;
  graph.objects = {Object(1, "coffee cup", 1.0), Object(2, "table", 2.0), Object(3, "sink", 3.0),
                   Object(4, "toilet", 4.0)};
  TargetSpec target;
  target.name = "cup";
  target.relation = "on";
  target.anchor = "table";
  // The prior is asked with canonical lexicon names: "table" is the COCO "dining table".
  const TablePrior prior({{{"cup", "sink"}, 0.4}, {{"cup", "dining table"}, 0.3}});
  const ExplorationContext context =
      BuildExplorationContext(target, graph, matcher_, &prior, nullptr);
  ASSERT_EQ(context.objects.size(), 3u);  // the toilet has no term: left out
  EXPECT_EQ(context.objects[0].label, "coffee cup");
  EXPECT_DOUBLE_EQ(context.objects[0].relevance, 0.5);  // Jaccard {coffee, cup} vs {cup}
  EXPECT_DOUBLE_EQ(context.objects[0].relation, 0.0);
  EXPECT_EQ(context.objects[1].label, "table");
  EXPECT_DOUBLE_EQ(context.objects[1].relevance, 0.0);
  EXPECT_DOUBLE_EQ(context.objects[1].relation, 1.0);  // anchor of "cup on table"
  EXPECT_DOUBLE_EQ(context.objects[1].cooccurrence, 0.3);
  EXPECT_EQ(context.objects[2].label, "sink");
  EXPECT_DOUBLE_EQ(context.objects[2].cooccurrence, 0.4);
  EXPECT_DOUBLE_EQ(context.objects[2].position.x(), 3.0);
  EXPECT_TRUE(context.visited.empty());
}

TEST_F(GatewayExplorationContextTest, VisitedPlacesComeFromMemoryAndRoomsGiveNoObjects) {
  TopologicalMemory memory(&matcher_, TopologicalMemoryConfig{});
  memory.Update(Eigen::Vector3d(0, 0, 0), {}, {});
  memory.Update(Eigen::Vector3d(3, 0, 0), {}, {});  // >= 2 m: a second node
  SceneGraph graph;
  graph.objects = {Object(1, "sink", 1.0)};
  TargetSpec kitchen;
  kitchen.name = "kitchen";
  kitchen.is_room = true;
  const TablePrior prior({{{"kitchen", "sink"}, 0.9}});
  const ExplorationContext context =
      BuildExplorationContext(kitchen, graph, matcher_, &prior, &memory);
  EXPECT_TRUE(context.objects.empty());
  ASSERT_EQ(context.visited.size(), 2u);
  EXPECT_DOUBLE_EQ(context.visited[1].x(), 3.0);
}

TEST_F(GatewayExplorationContextTest, RegionsOfTwoOrMoreObjectsGiveARoomHint) {
  SceneGraph graph;
  graph.objects = {Object(1, "sink", 1.0), Object(2, "oven", 3.0), Object(3, "toilet", 9.0),
                   Object(4, "cup", 2.0)};
  graph.regions = {{7, "area_with_sink_oven", {1, 2, 4}}, {8, "area_with_toilet", {3}}};
  TargetSpec target;
  target.name = "cup";
  const TablePrior prior({{{"cup", "sink"}, 0.4}, {{"cup", "oven"}, 0.2}});
  const ExplorationContext context =
      BuildExplorationContext(target, graph, matcher_, &prior, nullptr);
  // cup (relevance 1), sink, oven as objects; then the kitchen-like region: the seen cup is left
  // out of it, the room value is the default mean (0.4 + 0.2) / 2 at the mean of x = 1 and 3.
  // The one-object region gives no hint.
  ASSERT_EQ(context.objects.size(), 4u);
  const ExplorationHint& room = context.objects.back();
  EXPECT_EQ(room.label, "region:7");  // by id: region names grow with their objects
  EXPECT_DOUBLE_EQ(room.cooccurrence, 0.3);
  EXPECT_DOUBLE_EQ(room.position.x(), 2.0);
  EXPECT_DOUBLE_EQ(room.relevance, 0.0);
}

// The shipped ConceptNet prior (shared/data): objects found in the same places co-occur.
TEST(GatewayConceptNetCooccurrenceTest, SharedPriorRelatesKitchenwareNotBathroomware) {
  absl::StatusOr<ConceptNetCooccurrence> prior = ConceptNetCooccurrence::Load(SEMNAV_PRIOR_JSON);
  ASSERT_TRUE(prior.ok()) << prior.status();
  EXPECT_GT(prior->Cooccurrence("fork", "knife"), 0.6);  // the proxy's own test: > 0.6
  EXPECT_EQ(prior->Cooccurrence("fork", "toilet"), 0.0);
  EXPECT_NEAR(prior->Cooccurrence("sofa", "couch"), 1.0, 1e-12);  // canonical terms: sofa = couch
  EXPECT_EQ(prior->Cooccurrence("fire extinguisher", "knife"), 0.0);  // unknown to the prior
  // Places the prior has no object for: the target's AtLocation weight over its strongest place
  // (car: road 4.47 / city 7.48; boat: river 2.83 / water 8.25).
  EXPECT_NEAR(prior->Cooccurrence("car", "road"), 4.47213595499958 / 7.483314773547882, 1e-9);
  EXPECT_NEAR(prior->Cooccurrence("boat", "river"), 2.82842712474619 / 8.246211251235321, 1e-9);
  EXPECT_EQ(prior->Cooccurrence("boat", "road"), 0.0);
  // A room read from its objects: kitchenware says kitchen, where a fork is found, more than a
  // bathroom does; the cosine of the room's summed place distribution with the fork's.
  const double kitchen = prior->RoomCooccurrence("fork", {"knife", "oven", "sink"});
  const double bathroom = prior->RoomCooccurrence("fork", {"toilet", "toothbrush"});
  EXPECT_GT(kitchen, bathroom);
  EXPECT_GT(kitchen, 0.3);
  EXPECT_NEAR(prior->RoomCooccurrence("fork", {"knife"}), prior->Cooccurrence("fork", "knife"),
              1e-12);
  EXPECT_EQ(prior->RoomCooccurrence("fork", {"fire extinguisher"}), 0.0);  // nothing known
  EXPECT_EQ(ConceptNetCooccurrence::Load("/nonexistent/conceptnet.json").status().code(),
            absl::StatusCode::kNotFound);
}

}  // namespace
}  // namespace semnav::reasoning
