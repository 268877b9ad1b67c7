// Contract test of the exploration and trajectory RPCs of the real
// semnav-planning binary.
#include <grpcpp/client_context.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "semnav/common/v1/errors.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/planning/tests/planning_binary_test.h"

namespace semnav::planning {
namespace {

namespace pb = semnav::planning::v1;
using semnav::common::v1::GridMap;
using semnav::common::v1::Pose2D;

// The field an INVALID_ARGUMENT refusal names in its ErrorInfo; a test failure, and "", for any
// other status or a refusal without one.
std::string RefusedField(const grpc::Status& status) {
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << status.error_message();
  const std::optional<semnav::common::v1::ErrorInfo> info =
      GetDetail<semnav::common::v1::ErrorInfo>(status);
  EXPECT_TRUE(info.has_value()) << status.error_message();
  return info.has_value() ? info->field() : "";
}

// 1 m cells, origin (-1, -2), row 0 lowest: '.' explored free, '#' explored
// structure, '?' unexplored.
const std::vector<std::string> kRows = {
    "......??", "......??", "..##..??", "........", "???.....",
};

GridMap ExplorationGrid() {
  GridMap grid;
  grid.set_resolution(1.0);
  grid.mutable_origin()->set_x(-1.0);
  grid.mutable_origin()->set_y(-2.0);
  grid.set_width(8);
  grid.set_height(5);
  std::string hierarchical;
  std::string explored;
  for (const std::string& row : kRows) {
    for (char c : row) {
      hierarchical.push_back(static_cast<char>(c == '.' ? 0 : c == '#' ? 100 : 255));
      explored.push_back(static_cast<char>(c == '?' ? 0 : 1));
    }
  }
  auto* h = grid.add_layers();
  h->set_kind(semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  h->set_data(hierarchical);
  auto* e = grid.add_layers();
  e->set_kind(semnav::common::v1::GRID_LAYER_KIND_EXPLORED);
  e->set_data(explored);
  return grid;
}

Pose2D CellCentre(int col, int row) {
  Pose2D p;
  p.set_x(-1.0 + col + 0.5);
  p.set_y(-2.0 + row + 0.5);
  return p;
}

using ExplorationContract = PlanningBinaryTest;

pb::SelectExplorationGoalRequest GoalRequest(pb::ExplorationStrategy strategy) {
  pb::SelectExplorationGoalRequest request;
  *request.mutable_source()->mutable_grid() = ExplorationGrid();
  *request.mutable_robot() = CellCentre(0, 0);
  request.set_strategy(strategy);
  request.set_min_frontier_cells(1);
  return request;
}

TEST_F(ExplorationContract, ExtractFrontiersClustersAndScores) {
  pb::ExtractFrontiersRequest request;
  *request.mutable_source()->mutable_grid() = ExplorationGrid();
  *request.mutable_robot() = CellCentre(0, 0);
  request.set_min_cells(1);
  pb::ExtractFrontiersResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->ExtractFrontiers(&context, request, &response).ok());
  ASSERT_EQ(response.frontiers_size(), 2);
  // Right cluster: (5,0) (5,1) (5,2) (6,3) (7,3); path from (0,0) to (5,0) is 5 m.
  EXPECT_EQ(response.frontiers(0).size_cells(), 5u);
  EXPECT_DOUBLE_EQ(response.frontiers(0).path_distance_m(), 5.0);
  EXPECT_DOUBLE_EQ(response.frontiers(0).anchor().x(), CellCentre(5, 2).x());
  // Left cluster: (0,3) (1,3) (2,3) (3,4); 3 m away.
  EXPECT_EQ(response.frontiers(1).size_cells(), 4u);
  EXPECT_DOUBLE_EQ(response.frontiers(1).path_distance_m(), 3.0);
  EXPECT_DOUBLE_EQ(response.frontiers(1).score().distance(), 1.0 - 3.0 / 5.0);
  EXPECT_DOUBLE_EQ(response.frontiers(1).score().novelty(), 1.0);
}

pb::Frontier FrontierAt(double x, double y, double path_distance_m) {
  pb::Frontier f;
  f.mutable_centroid()->set_x(x);
  f.mutable_centroid()->set_y(y);
  f.set_path_distance_m(path_distance_m);
  return f;
}

// Robot at the origin; A (2, 0) 2 m away by path, B (0, 4) 4 m, C (-3, 0)
// unreachable; a relevant sofa at (0, 5) next to B; visited place (2, 1).
pb::ScoreFrontiersRequest ScoreRequest() {
  pb::ScoreFrontiersRequest request;
  *request.add_frontiers() = FrontierAt(2, 0, 2);
  *request.add_frontiers() = FrontierAt(0, 4, 4);
  *request.add_frontiers() = FrontierAt(-3, 0, -1);
  pb::SemanticObject* sofa = request.mutable_semantics()->add_objects();
  sofa->mutable_position()->set_y(5.0);
  sofa->set_relevance(0.8);
  sofa->set_cooccurrence(0.5);
  Pose2D visited;
  visited.set_x(2.0);
  visited.set_y(1.0);
  *request.mutable_semantics()->add_visited() = visited;
  return request;
}

TEST_F(ExplorationContract, ScoreFrontiersUsesTheConfigOrRequestWeights) {
  pb::ScoreFrontiersResponse response;
  {
    grpc::ClientContext context;
    ASSERT_TRUE(Stub()->ScoreFrontiers(&context, ScoreRequest(), &response).ok());
  }
  ASSERT_EQ(response.scores_size(), 3);
  // A: distance 1 - 2/4, novelty 1 m / 3 m, sofa 5.4 m away and at 90 deg.
  EXPECT_DOUBLE_EQ(response.scores(0).distance(), 0.5);
  EXPECT_DOUBLE_EQ(response.scores(0).novelty(), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(response.scores(0).language(), 0.0);
  EXPECT_DOUBLE_EQ(response.scores(0).grounding(), 0.0);
  EXPECT_NEAR(response.scores(0).total(), 0.2 * 0.5 + 0.3 / 3.0, 1e-12);
  // B: farthest (0), novel, sofa 1 m away and straight ahead: language 0.8,
  // grounding (0.8 gradient + 0 relation + 0.5 co-occurrence) / 3.
  EXPECT_DOUBLE_EQ(response.scores(1).distance(), 0.0);
  EXPECT_DOUBLE_EQ(response.scores(1).language(), 0.8);
  EXPECT_NEAR(response.scores(1).grounding(), 1.3 / 3.0, 1e-12);
  EXPECT_NEAR(response.scores(1).total(), 0.3 + 0.2 * 0.8 + 0.3 * 1.3 / 3.0, 1e-12);
  // C is unreachable: distance 0, and never the best.
  EXPECT_DOUBLE_EQ(response.scores(2).distance(), 0.0);
  EXPECT_EQ(response.best_index(), 1);

  // Distance only: the nearest reachable frontier wins.
  pb::ScoreFrontiersRequest nearest = ScoreRequest();
  nearest.mutable_weights()->set_distance(1.0);
  nearest.mutable_weights()->set_novelty(0.0);
  nearest.mutable_weights()->set_language(0.0);
  nearest.mutable_weights()->set_grounding(0.0);
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->ScoreFrontiers(&context, nearest, &response).ok());
  EXPECT_DOUBLE_EQ(response.scores(0).total(), 0.5);
  EXPECT_DOUBLE_EQ(response.scores(1).total(), 0.0);
  EXPECT_EQ(response.best_index(), 0);
}

TEST_F(ExplorationContract, ScoreFrontiersNamesTheBadField) {
  pb::ScoreFrontiersRequest bad_weight = ScoreRequest();
  bad_weight.mutable_weights()->set_grounding(-0.3);
  pb::ScoreFrontiersRequest bad_distance = ScoreRequest();
  bad_distance.mutable_frontiers(1)->set_path_distance_m(std::nan(""));
  for (const auto& [request, field] : {std::pair{bad_weight, "weights.grounding"},
                                       std::pair{bad_distance, "frontiers[1].path_distance_m"}}) {
    pb::ScoreFrontiersResponse response;
    grpc::ClientContext context;
    const grpc::Status status = Stub()->ScoreFrontiers(&context, request, &response);
    EXPECT_EQ(RefusedField(status), field);
  }
  // No frontiers: nothing to score, nothing best.
  pb::ScoreFrontiersResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->ScoreFrontiers(&context, pb::ScoreFrontiersRequest(), &response).ok());
  EXPECT_EQ(response.scores_size(), 0);
  EXPECT_EQ(response.best_index(), -1);
}

TEST_F(ExplorationContract, NearestFrontierIsTheClosestByPath) {
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()
                  ->SelectExplorationGoal(
                      &context, GoalRequest(pb::EXPLORATION_STRATEGY_UNSPECIFIED), &response)
                  .ok());
  EXPECT_EQ(response.strategy(), pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER);
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(0, 3).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(0, 3).y());
  EXPECT_DOUBLE_EQ(response.score(), 3.0);
}

TEST_F(ExplorationContract, ARobotJustOutsideTheMapItDrewGetsAGoal) {
  // At the start the camera has not seen the cell the robot stands on, so the map can end in
  // front of it (the hold-out clinic ward's east start: "robot ... is outside the grid", and the
  // robot drove a blind fallback step into the wall behind it for 15 s). One cell (1 m, the
  // planning default max_start_outside_m) left of column 0, the grid grows to the robot with a
  // passable, unexplored strip, so column 0's explored cells border the unknown: the nearest
  // frontier cell is (0, 0), one cell away.
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER);
  *request.mutable_robot() = CellCentre(-1, 0);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  const grpc::Status status = Stub()->SelectExplorationGoal(&context, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(0, 0).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(0, 0).y());
  EXPECT_DOUBLE_EQ(response.score(), 1.0);
  // Three cells out (3 m) is no robot of this map: refused by name.
  *request.mutable_robot() = CellCentre(-3, 0);
  grpc::ClientContext far_context;
  const grpc::Status far = Stub()->SelectExplorationGoal(&far_context, request, &response);
  EXPECT_EQ(RefusedField(far), "robot");
}

TEST_F(ExplorationContract, AGroundRobotsGoalIsWhereItsFootprintStands) {
  // A 1 m footprint inflates the structure and the unknown by one cell: the nearest frontier
  // cell (0,3) borders the unknown at (0,4), so the robot stands at (0,2), 2 cells up, and
  // reaches it from there (score 3, as before).
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER);
  request.set_robot_radius_m(1.0);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(0, 2).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(0, 2).y());
  EXPECT_DOUBLE_EQ(response.score(), 3.0);
  // PlanPath with that footprint reaches the answer as given.
  pb::PlanPathRequest plan;
  *plan.mutable_source()->mutable_grid() = ExplorationGrid();
  *plan.mutable_start() = CellCentre(0, 0);
  *plan.mutable_goal() = response.goal();
  plan.set_robot_radius_m(1.0);
  pb::PlanPathResponse path;
  grpc::ClientContext plan_context;
  ASSERT_TRUE(Stub()->PlanPath(&plan_context, plan, &path).ok());
  EXPECT_FALSE(path.goal_adjusted());
  // A radius that is not a finite number in [0, 5] m is refused by name.
  for (const double bad : {-1.0, 6.0, std::nan("")}) {
    request.set_robot_radius_m(bad);
    grpc::ClientContext bad_context;
    const grpc::Status status = Stub()->SelectExplorationGoal(&bad_context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_NE(status.error_message().find("robot_radius_m"), std::string::npos);
  }
}

TEST_F(ExplorationContract, ExcludedGoalsRemoveTheirFrontierCells) {
  // The left cluster's nearest cell (0,3) was spent; a 1.2 m radius removes (0,3) and (1,3).
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER);
  *request.add_excluded_goals() = CellCentre(0, 3);
  request.set_excluded_radius_m(1.2);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(2, 3).x());  // what is left of the cluster
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(2, 3).y());
  // Both clusters spent: nothing left to explore.
  *request.add_excluded_goals() = CellCentre(2, 3);
  *request.add_excluded_goals() = CellCentre(3, 4);
  *request.add_excluded_goals() = CellCentre(5, 1);
  *request.add_excluded_goals() = CellCentre(6, 3);
  grpc::ClientContext context2;
  const grpc::Status none = Stub()->SelectExplorationGoal(&context2, request, &response);
  EXPECT_EQ(none.error_code(), grpc::StatusCode::NOT_FOUND);
  // A negative radius names the field.
  request.set_excluded_radius_m(-1.0);
  grpc::ClientContext context3;
  const grpc::Status bad = Stub()->SelectExplorationGoal(&context3, request, &response);
  EXPECT_EQ(bad.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_NE(bad.error_message().find("excluded_radius_m"), std::string::npos);
}

pb::SearchArea Area(double min_x, double min_y, double max_x, double max_y) {
  pb::SearchArea area;
  area.set_min_x(min_x);
  area.set_min_y(min_y);
  area.set_max_x(max_x);
  area.set_max_y(max_y);
  return area;
}

TEST_F(ExplorationContract, SearchAreaDropsFrontierCellsOutsideIt) {
  // Area x in [3, 7] = columns 4..7: the left cluster (columns 0..3) is outside, so the nearest
  // frontier is the right cluster's (5,0), 5 m by path, not (0,3) at 3 m.
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER);
  *request.mutable_search_area() = Area(3.0, -2.0, 7.0, 3.0);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(5, 0).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(5, 0).y());
  EXPECT_DOUBLE_EQ(response.score(), 5.0);
  // An area holding no frontier cell: nothing to explore.
  *request.mutable_search_area() = Area(-1.0, -2.0, 2.0, 0.0);
  grpc::ClientContext context2;
  EXPECT_EQ(Stub()->SelectExplorationGoal(&context2, request, &response).error_code(),
            grpc::StatusCode::NOT_FOUND);
}

TEST_F(ExplorationContract, SearchAreaBoundsEveryStrategy) {
  // Semantic pull toward the left cluster; the area x in [3, 7] keeps only the right one (and
  // counts the left EROIs as explored). From (5,3), where EROI's 3 m roadmap reaches viewpoints.
  for (pb::ExplorationStrategy strategy :
       {pb::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER, pb::EXPLORATION_STRATEGY_EROI_UTILITY}) {
    pb::SelectExplorationGoalRequest request = GoalRequest(strategy);
    *request.mutable_robot() = CellCentre(5, 3);
    pb::SemanticObject* sofa = request.mutable_semantics()->add_objects();
    sofa->set_label("sofa");
    sofa->mutable_position()->set_x(0.0);
    sofa->mutable_position()->set_y(2.5);
    sofa->set_relevance(1.0);
    *request.mutable_search_area() = Area(3.0, -2.0, 7.0, 3.0);
    pb::SelectExplorationGoalResponse response;
    grpc::ClientContext context;
    ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok()) << strategy;
    EXPECT_GE(response.goal().x(), 3.0) << strategy;
  }
  // COVERAGE_MAX heads +x to (6,0) on the whole map; the area x <= 5 keeps it at column 5 or less.
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_COVERAGE_MAX);
  *request.mutable_search_area() = Area(-1.0, -2.0, 5.0, 3.0);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  EXPECT_LE(response.goal().x(), 5.0);
}

TEST_F(ExplorationContract, InvalidSearchAreaNamesTheField) {
  for (const pb::SearchArea& area : {Area(1.0, 0.0, 1.0, 2.0), Area(0.0, 3.0, 2.0, 1.0),
                                     Area(std::nan(""), 0.0, 2.0, 2.0), pb::SearchArea()}) {
    pb::SelectExplorationGoalRequest request =
        GoalRequest(pb::EXPLORATION_STRATEGY_NEAREST_FRONTIER);
    *request.mutable_search_area() = area;
    pb::SelectExplorationGoalResponse response;
    grpc::ClientContext context;
    const grpc::Status status = Stub()->SelectExplorationGoal(&context, request, &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << area.ShortDebugString();
    EXPECT_NE(status.error_message().find("search_area"), std::string::npos);
  }
}

// SEMANTIC_FRONTIER with a sofa of relevance 1 beside the right cluster.
pb::SelectExplorationGoalRequest SofaBesideTheRightCluster() {
  pb::SelectExplorationGoalRequest request =
      GoalRequest(pb::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER);
  pb::SemanticObject* sofa = request.mutable_semantics()->add_objects();
  sofa->set_label("sofa");
  sofa->mutable_position()->set_x(6.0);
  sofa->mutable_position()->set_y(-1.5);
  sofa->set_relevance(1.0);
  return request;
}

TEST_F(ExplorationContract, SemanticFrontierFollowsTheRelevantObject) {
  pb::SelectExplorationGoalRequest request = SofaBesideTheRightCluster();
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(5, 2).x());  // the right cluster's anchor
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(5, 2).y());
}

TEST_F(ExplorationContract, SemanticFrontierTakesTheDiscountOnlyOnConfiguredPlatforms) {
  // The default config gives no platform the discount: a ground robot's request gets the seed
  // total's choice, the right cluster's anchor (5, 2), like an unspecified one.
  pb::SelectExplorationGoalRequest request = SofaBesideTheRightCluster();
  request.set_platform(pb::EXPLORATION_PLATFORM_GROUND);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(5, 2).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(5, 2).y());

  // A planning configured with `semantic_discount: {platforms: [ground]}`: without evidence the
  // nearest frontier wins (the upper-left cluster, 3 m, as NEAREST_FRONTIER); the sofa's
  // relevance pulls the robot to the right cluster's nearest cell (5, 0), not its anchor. An
  // aerial robot keeps the seed total.
  const std::string config = ::testing::TempDir() + "/planning_discount_ground.yaml";
  std::ofstream(config) << "planning:\n  exploration:\n"
                           "    semantic_discount: {platforms: [ground]}\n";
  absl::StatusOr<std::unique_ptr<testing::ServiceProcess>> ground_planning =
      testing::ServiceProcess::Start("semnav-planning", {"--config", config});
  ASSERT_TRUE(ground_planning.ok()) << ground_planning.status();
  std::unique_ptr<pb::PlanningService::Stub> stub =
      pb::PlanningService::NewStub((*ground_planning)->channel());
  pb::SelectExplorationGoalRequest plain = request;
  plain.mutable_semantics()->clear_objects();
  grpc::ClientContext plain_context;
  ASSERT_TRUE(stub->SelectExplorationGoal(&plain_context, plain, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(0, 3).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(0, 3).y());
  grpc::ClientContext ground_context;
  ASSERT_TRUE(stub->SelectExplorationGoal(&ground_context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(5, 0).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(5, 0).y());
  request.set_platform(pb::EXPLORATION_PLATFORM_AERIAL);
  grpc::ClientContext aerial_context;
  ASSERT_TRUE(stub->SelectExplorationGoal(&aerial_context, request, &response).ok());
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(5, 2).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(5, 2).y());

  request.set_platform(static_cast<pb::ExplorationPlatform>(42));
  grpc::ClientContext bad_context;
  const grpc::Status bad = stub->SelectExplorationGoal(&bad_context, request, &response);
  EXPECT_EQ(RefusedField(bad), "platform");

  // An unknown platform name in the config is refused at start, naming the key.
  const std::string wrong = ::testing::TempDir() + "/planning_discount_wrong.yaml";
  std::ofstream(wrong) << "planning:\n  exploration:\n"
                          "    semantic_discount: {platforms: [boat]}\n";
  absl::StatusOr<testing::ProcessResult> refused =
      testing::RunToCompletion("semnav-planning", {"--config", wrong});
  ASSERT_TRUE(refused.ok()) << refused.status();
  EXPECT_NE(refused->exit_code, 0);
  EXPECT_NE(refused->output.find("semantic_discount.platforms"), std::string::npos)
      << refused->output;
}

TEST_F(ExplorationContract, CoverageMaxGoesToTheBoundaryAhead) {
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_COVERAGE_MAX);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SelectExplorationGoal(&context, request, &response).ok());
  // Heading +x from (0,0): sqrt2 * 8 / 2 = 5.66 cells ahead -> (6,0).
  EXPECT_DOUBLE_EQ(response.goal().x(), CellCentre(6, 0).x());
  EXPECT_DOUBLE_EQ(response.goal().y(), CellCentre(6, 0).y());
}

TEST_F(ExplorationContract, EroiUtilityAndItsBadInput) {
  // From (5,3) the roadmap (edges <= 3 m) reaches the viewpoints of the
  // partly explored EROIs on the right.
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_EROI_UTILITY);
  *request.mutable_robot() = CellCentre(5, 3);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  const grpc::Status ok = Stub()->SelectExplorationGoal(&context, request, &response);
  ASSERT_TRUE(ok.ok()) << ok.error_message();
  EXPECT_GT(response.score(), 0.0);
  ASSERT_GE(response.route_size(), 2);
  EXPECT_DOUBLE_EQ(response.route(0).x(), CellCentre(5, 3).x());
  EXPECT_DOUBLE_EQ(response.route(0).y(), CellCentre(5, 3).y());

  // From (0,0) no viewpoint lies within the roadmap's 3 m edges; the robot still reaches them
  // by its path through explored free space (issue 15: it used to get NOT_FOUND, and a UAV in
  // wide explored space then took blind steps out of the world).
  grpc::ClientContext far_context;
  const grpc::Status far = Stub()->SelectExplorationGoal(
      &far_context, GoalRequest(pb::EXPLORATION_STRATEGY_EROI_UTILITY), &response);
  ASSERT_TRUE(far.ok()) << far.error_message();
  EXPECT_GT(response.score(), 0.0);
  ASSERT_GE(response.route_size(), 2);
  EXPECT_DOUBLE_EQ(response.route(0).x(), CellCentre(0, 0).x());
  EXPECT_DOUBLE_EQ(response.route(0).y(), CellCentre(0, 0).y());

  pb::SelectExplorationGoalRequest bad = GoalRequest(pb::EXPLORATION_STRATEGY_EROI_UTILITY);
  bad.add_eroi_semantic_values(0.5);  // the grid has 4 x 3 EROIs of 2 m
  grpc::ClientContext bad_context;
  const grpc::Status status = Stub()->SelectExplorationGoal(&bad_context, bad, &response);
  EXPECT_EQ(RefusedField(status), "eroi_semantic_values");

  // The caller's EROI edge: 12 values fit 2 m EROIs, not 4 m ones (2 x 2 of them); an edge below
  // 0.1 m is refused by field.
  pb::SelectExplorationGoalRequest wide = GoalRequest(pb::EXPLORATION_STRATEGY_EROI_UTILITY);
  for (int i = 0; i < 4; ++i) wide.add_eroi_semantic_values(0.25);
  wide.set_eroi_size_m(4.0);
  grpc::ClientContext wide_context;
  const grpc::Status wide_status = Stub()->SelectExplorationGoal(&wide_context, wide, &response);
  EXPECT_NE(wide_status.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
      << wide_status.error_message();
  wide.set_eroi_size_m(0.05);
  grpc::ClientContext tiny_context;
  const grpc::Status tiny = Stub()->SelectExplorationGoal(&tiny_context, wide, &response);
  EXPECT_EQ(RefusedField(tiny), "eroi_size_m");
}

TEST_F(ExplorationContract, ALookAtASightingGoesRoundTheStructureTheMapKnows) {
  // Row 3 is free: from (-0.5, 1.5) the look at (6.5, 1.5) from 3 m is (3.5, 1.5), whatever the
  // strategy.
  pb::SelectExplorationGoalRequest request = GoalRequest(pb::EXPLORATION_STRATEGY_EROI_UTILITY);
  *request.mutable_robot() = CellCentre(0, 3);
  *request.mutable_look_at() = CellCentre(7, 3);
  request.set_look_distance_m(3.0);
  pb::SelectExplorationGoalResponse response;
  grpc::ClientContext context;
  grpc::Status status = Stub()->SelectExplorationGoal(&context, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_DOUBLE_EQ(response.goal().x(), 3.5);
  EXPECT_DOUBLE_EQ(response.goal().y(), 1.5);
  EXPECT_DOUBLE_EQ(response.score(), 4.0);
  EXPECT_EQ(response.route_size(), 0);
  // Row 2 has the structure at x in [1, 3), 2 and 3 m along the line from (-0.5, 0.5). The
  // straight look (x = 3.5, 4 m along) is within the 1 m look clearance plus half a cell's
  // diagonal (1.707 m) of it; the seen free cell nearest it and clear of the structure is
  // column 5, 5 m along: (4.5, 0.5), beyond the structure.
  *request.mutable_robot() = CellCentre(0, 2);
  *request.mutable_look_at() = CellCentre(7, 2);
  grpc::ClientContext wall_context;
  status = Stub()->SelectExplorationGoal(&wall_context, request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_DOUBLE_EQ(response.goal().x(), 4.5);
  EXPECT_DOUBLE_EQ(response.goal().y(), 0.5);
  EXPECT_DOUBLE_EQ(response.score(), 5.0);
  // A look point that is not a finite pose, or a distance outside [0, 50] m, is refused by name.
  pb::SelectExplorationGoalRequest bad_point = request;
  bad_point.mutable_look_at()->set_x(std::nan(""));
  pb::SelectExplorationGoalRequest bad_distance = request;
  bad_distance.set_look_distance_m(51.0);
  for (const auto& [bad, field] :
       {std::pair{bad_point, "look_at"}, std::pair{bad_distance, "look_distance_m"}}) {
    grpc::ClientContext bad_context;
    const grpc::Status refused = Stub()->SelectExplorationGoal(&bad_context, bad, &response);
    const std::string named = RefusedField(refused);
    EXPECT_EQ(named.rfind(field, 0), 0u) << named;
  }
}

TEST_F(ExplorationContract, SmoothTrajectoryRespectsTheLimits) {
  pb::SmoothTrajectoryRequest request;
  *request.mutable_source()->mutable_grid() = ExplorationGrid();
  for (auto [c, r] : {std::pair{0, 0}, std::pair{4, 0}, std::pair{4, 3}}) {
    *request.add_path() = CellCentre(c, r);
  }
  pb::SmoothTrajectoryResponse response;
  grpc::ClientContext context;
  ASSERT_TRUE(Stub()->SmoothTrajectory(&context, request, &response).ok());
  ASSERT_GT(response.points_size(), 10);
  EXPECT_DOUBLE_EQ(response.points(0).pose().x(), CellCentre(0, 0).x());
  EXPECT_DOUBLE_EQ(response.points(response.points_size() - 1).pose().y(), CellCentre(4, 3).y());
  EXPECT_DOUBLE_EQ(response.points(0).speed_mps(), 0.0);
  EXPECT_GT(response.duration_s(), 7.0);  // more than 7 m of path at <= 1 m/s
  for (const pb::TrajectoryPoint& p : response.points()) EXPECT_LE(p.speed_mps(), 1.0 + 1e-12);

  pb::SmoothTrajectoryRequest blocked = request;
  *blocked.mutable_path(1) = CellCentre(2, 2);  // structure
  grpc::ClientContext bad_context;
  const grpc::Status status = Stub()->SmoothTrajectory(&bad_context, blocked, &response);
  EXPECT_EQ(RefusedField(status), "path[1]");
}

}  // namespace
}  // namespace semnav::planning
