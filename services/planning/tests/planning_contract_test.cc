// Contract test: the real semnav-planning binary on a loopback port, called
// through the generated stubs.
#include <grpcpp/client_context.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "semnav/common/v1/errors.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "services/planning/core/random_layered_map.h"
#include "services/planning/tests/planning_binary_test.h"

namespace semnav::planning {
namespace {

namespace pb = semnav::planning::v1;
using semnav::common::v1::GridMap;

// A GridMap with one HIERARCHICAL layer drawn as rows ('.' 0, '#' 100,
// digits d -> obstacle height 10 d); row 0 is the lowest y.
GridMap MakeGrid(const std::vector<std::string>& rows, double resolution) {
  GridMap grid;
  grid.set_resolution(resolution);
  grid.mutable_origin()->set_x(-1.0);
  grid.mutable_origin()->set_y(-2.0);
  grid.set_width(static_cast<uint32_t>(rows[0].size()));
  grid.set_height(static_cast<uint32_t>(rows.size()));
  grid.set_revision(7);
  auto* layer = grid.add_layers();
  layer->set_kind(semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  std::string data;
  for (const std::string& row : rows) {
    for (char c : row)
      data.push_back(static_cast<char>(c == '.' ? 0 : c == '#' ? 100 : 10 * (c - '0')));
  }
  layer->set_data(data);
  return grid;
}

// Cell (col, row) centre in the frame of MakeGrid.
semnav::common::v1::Pose2D At(int col, int row, double resolution) {
  semnav::common::v1::Pose2D pose;
  pose.set_x(-1.0 + (col + 0.5) * resolution);
  pose.set_y(-2.0 + (row + 0.5) * resolution);
  return pose;
}

class PlanningContract : public PlanningBinaryTest {
 protected:
  grpc::Status Plan(const pb::PlanPathRequest& request, pb::PlanPathResponse* response,
                    int deadline_ms = 10000) {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::milliseconds(deadline_ms));
    return Stub()->PlanPath(&context, request, response);
  }
};

// A wall with a one-cell door at column 3: 0.5 m cells.
const std::vector<std::string> kDoorRows = {
    ".......", ".......", "###.###", ".......", ".......",
};

pb::PlanPathRequest DoorRequest(pb::PlannerKind planner) {
  pb::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = MakeGrid(kDoorRows, 0.5);
  *request.mutable_start() = At(0, 0, 0.5);
  *request.mutable_goal() = At(6, 4, 0.5);
  request.set_planner(planner);
  return request;
}

TEST_F(PlanningContract, JpsAndAStarGiveTheSameOptimalPath) {
  // (0,0) -> (6,4) through the door (3,2) without corner cutting:
  // (0,0)->(3,1) is 2 + sqrt2, (3,1)->(3,3) is 2, (3,3)->(6,4) is 2 + sqrt2.
  const double expected_m = (6 + 2 * std::sqrt(2.0)) * 0.5;
  for (pb::PlannerKind kind : {pb::PLANNER_KIND_JPS, pb::PLANNER_KIND_ASTAR}) {
    pb::PlanPathResponse response;
    const grpc::Status status = Plan(DoorRequest(kind), &response);
    ASSERT_TRUE(status.ok()) << status.error_message();
    EXPECT_NEAR(response.length_m(), expected_m, 1e-9) << kind;
    EXPECT_NEAR(response.path(0).x(), -0.75, 1e-12);
    EXPECT_NEAR(response.path(0).y(), -1.75, 1e-12);
    EXPECT_NEAR(response.path(response.path_size() - 1).x(), 2.25, 1e-12);
    EXPECT_EQ(response.segments_size(), 1);
    EXPECT_EQ(response.segments(0).mode(), pb::MOTION_MODE_ROLLING);
    EXPECT_EQ(response.map_revision(), 7u);
    EXPECT_FALSE(response.alternative_used());
  }
}

TEST_F(PlanningContract, FootprintInflationBlocksTheDoor) {
  pb::PlanPathRequest request = DoorRequest(pb::PLANNER_KIND_JPS);
  request.set_robot_radius_m(0.5);  // one cell: the door closes
  pb::PlanPathResponse response;
  const grpc::Status status = Plan(request, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  std::optional<pb::PlanFailureDetail> detail = GetDetail<pb::PlanFailureDetail>(status);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->reason(), pb::PLAN_FAILURE_REASON_NO_PATH);
  // Clients that only read ErrorInfo see the typed failure too.
  std::optional<semnav::common::v1::ErrorInfo> info =
      GetDetail<semnav::common::v1::ErrorInfo>(status);
  ASSERT_TRUE(info.has_value());
  EXPECT_EQ(info->reason(), "NO_PATH");
}

TEST_F(PlanningContract, TypedFailuresForOccupiedEndpoints) {
  pb::PlanPathRequest request = DoorRequest(pb::PLANNER_KIND_JPS);
  *request.mutable_goal() = At(0, 2, 0.5);  // on the wall
  pb::PlanPathResponse response;
  grpc::Status status = Plan(request, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  std::optional<pb::PlanFailureDetail> detail = GetDetail<pb::PlanFailureDetail>(status);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->reason(), pb::PLAN_FAILURE_REASON_GOAL_OCCUPIED);
  EXPECT_EQ(detail->goal_column(), 0u);
  EXPECT_EQ(detail->goal_row(), 2u);

  // A start in the wall snaps to the nearest free cell (within start_snap_radius_m, 0.5 m).
  request = DoorRequest(pb::PLANNER_KIND_ASTAR);
  *request.mutable_start() = At(6, 2, 0.5);
  status = Plan(request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_TRUE(response.start_adjusted());
  EXPECT_NEAR(response.path(0).x(), At(6, 2, 0.5).x(), 1e-12);  // begins where the robot is
  EXPECT_NEAR(response.path(0).y(), At(6, 2, 0.5).y(), 1e-12);
  EXPECT_NEAR(response.planned_start().x(), At(6, 3, 0.5).x(), 1e-12);
  EXPECT_NEAR(response.planned_start().y(), At(6, 3, 0.5).y(), 1e-12);

  // No free cell within the snap radius: the typed failure stays.
  request.set_robot_radius_m(1.0);  // two cells: the wall's inflation covers the whole map
  response.Clear();
  status = Plan(request, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  detail = GetDetail<pb::PlanFailureDetail>(status);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->reason(), pb::PLAN_FAILURE_REASON_START_OCCUPIED);
}

void ExpectFieldError(const grpc::Status& status, const std::string& field);

TEST_F(PlanningContract, StartJustOutsideTheGridIsPlannedFrom) {
  pb::PlanPathRequest request = DoorRequest(pb::PLANNER_KIND_JPS);
  request.mutable_start()->set_x(-1.2);  // 0.2 m left of the grid's origin (-1, -2)
  pb::PlanPathResponse response;
  grpc::Status status = Plan(request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_TRUE(response.grid_padded());
  EXPECT_NEAR(response.path(0).x(), -1.25, 1e-12);  // the padded column's centre
  EXPECT_NEAR(response.path(response.path_size() - 1).x(), 2.25, 1e-12);
  // Farther out than max_start_outside_m (1 m): an error naming the start.
  request.mutable_start()->set_x(-3.0);
  ExpectFieldError(Plan(request, &response), "start");

  // A goal 0.2 m past the right edge (x = 2.5): planned to the edge cell, column 6.
  request = DoorRequest(pb::PLANNER_KIND_JPS);
  request.mutable_goal()->set_x(2.7);
  response.Clear();
  status = Plan(request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_TRUE(response.goal_adjusted());
  EXPECT_NEAR(response.planned_goal().x(), 2.25, 1e-12);
}

TEST_F(PlanningContract, AlternativePointForAGoalInTheWall) {
  pb::PlanPathRequest request = DoorRequest(pb::PLANNER_KIND_JPS);
  *request.mutable_goal() = At(5, 2, 0.5);  // a TV in the wall
  request.set_allow_alternative_point(true);
  *request.mutable_first_sighting() = At(5, 0, 0.5);
  pb::PlanPathResponse response;
  const grpc::Status status = Plan(request, &response);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_TRUE(response.alternative_used());
  EXPECT_NEAR(response.planned_goal().x(), At(5, 1, 0.5).x(), 1e-12);
  EXPECT_NEAR(response.planned_goal().y(), At(5, 1, 0.5).y(), 1e-12);
  EXPECT_FALSE(response.adjustment_reason().empty());
}

// Seed 003 multi-modal case: a 5-cell obstacle wall (rows 0-3) with a gap
// at row 4; 1 m cells.
pb::PlanPathRequest WallRequest(double beta) {
  std::vector<std::string> rows(7, std::string(21, '.'));
  for (int y = 0; y <= 3; ++y) {
    for (int x = 8; x <= 12; ++x) rows[y][x] = '6';
  }
  pb::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = MakeGrid(rows, 1.0);
  *request.mutable_start() = At(0, 0, 1.0);
  *request.mutable_goal() = At(20, 0, 1.0);
  request.set_planner(pb::PLANNER_KIND_JUMP_ASTAR);
  request.mutable_multimodal()->set_beta(beta);
  return request;
}

TEST_F(PlanningContract, JumpAStarFliesOrRollsByBeta) {
  pb::PlanPathResponse fly;
  ASSERT_TRUE(Plan(WallRequest(1.0), &fly).ok());
  EXPECT_NEAR(fly.fly_m(), 6.0, 1e-9);
  EXPECT_NEAR(fly.roll_m(), 14.0, 1e-9);
  EXPECT_EQ(fly.mode_switches(), 2u);
  EXPECT_NEAR(fly.energy_j(), 6 * 800.0 + 14 * 400.0, 1e-6);
  ASSERT_EQ(fly.segments_size(), 3);
  EXPECT_EQ(fly.segments(1).mode(), pb::MOTION_MODE_FLYING);
  EXPECT_NEAR(fly.path(fly.segments(1).first_point()).x(), -1.0 + 7.5, 1e-9);

  pb::PlanPathResponse roll;
  ASSERT_TRUE(Plan(WallRequest(5.0), &roll).ok());
  EXPECT_DOUBLE_EQ(roll.fly_m(), 0.0);
  EXPECT_EQ(roll.mode_switches(), 0u);
  EXPECT_NEAR(roll.roll_m(), 12 + 8 * std::sqrt(2.0), 1e-9);
}

// The seed 003 map (800 x 800 cells at 5 cm) as an inline HIERARCHICAL grid.
pb::PlanPathRequest SeedMapRequest(const RandomLayeredMap& map) {
  GridMap grid;
  grid.set_resolution(0.05);
  grid.set_width(static_cast<uint32_t>(map.grid.width()));
  grid.set_height(static_cast<uint32_t>(map.grid.height()));
  auto* layer = grid.add_layers();
  layer->set_kind(semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  layer->set_data(std::string(map.grid.values().begin(), map.grid.values().end()));
  pb::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = std::move(grid);
  request.mutable_start()->set_x((map.start.x + 0.5) * 0.05);
  request.mutable_start()->set_y((map.start.y + 0.5) * 0.05);
  request.mutable_goal()->set_x((map.goal.x + 0.5) * 0.05);
  request.mutable_goal()->set_y((map.goal.y + 0.5) * 0.05);
  request.set_planner(pb::PLANNER_KIND_JUMP_ASTAR);
  return request;
}

// The service keeps a map's Jump A* tables and builds its landmark bound
// off the query path, so repeated queries search far less for the same path.
TEST_F(PlanningContract, JumpAStarReusesItsPerMapStateWithTheSameResult) {
  RandomLayeredMap map = MakeRandomLayeredMap({});
  pb::PlanPathResponse cold;
  ASSERT_TRUE(Plan(SeedMapRequest(map), &cold).ok());
  pb::PlanPathResponse warm;
  for (int attempt = 0; attempt < 200; ++attempt) {  // the landmarks take ~1 s to appear
    ASSERT_TRUE(Plan(SeedMapRequest(map), &warm).ok());
    if (warm.expansions() < cold.expansions()) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_LT(warm.expansions() * 10, cold.expansions());
  EXPECT_DOUBLE_EQ(warm.length_m(), cold.length_m());
  EXPECT_DOUBLE_EQ(warm.fly_m(), cold.fly_m());
  EXPECT_DOUBLE_EQ(warm.energy_j(), cold.energy_j());
  EXPECT_EQ(warm.mode_switches(), cold.mode_switches());
  RecordProperty("cold_planning_ms", std::to_string(cold.planning_time_ms()));
  RecordProperty("warm_planning_ms", std::to_string(warm.planning_time_ms()));
  // One changed cell (off the path, in a far corner) is another map: cold again.
  map.grid.at(map.grid.width() - 5, 4) = 50;
  pb::PlanPathResponse changed;
  ASSERT_TRUE(Plan(SeedMapRequest(map), &changed).ok());
  EXPECT_EQ(changed.expansions(), cold.expansions());
}

TEST_F(PlanningContract, TimeoutIsDeadlineExceededWithTypedReason) {
  // 1200 x 1200 cells with a long wall: A* floods most of the map.
  std::vector<std::string> rows(1200, std::string(1200, '.'));
  for (int y = 0; y < 1199; ++y) rows[y][600] = '#';
  pb::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = MakeGrid(rows, 0.05);
  *request.mutable_start() = At(0, 0, 0.05);
  *request.mutable_goal() = At(1199, 0, 0.05);
  request.set_planner(pb::PLANNER_KIND_ASTAR);
  request.set_max_planning_time_ms(1);
  pb::PlanPathResponse response;
  const grpc::Status status = Plan(request, &response);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::DEADLINE_EXCEEDED);
  std::optional<pb::PlanFailureDetail> detail = GetDetail<pb::PlanFailureDetail>(status);
  ASSERT_TRUE(detail.has_value());
  EXPECT_EQ(detail->reason(), pb::PLAN_FAILURE_REASON_TIMEOUT);
}

void ExpectFieldError(const grpc::Status& status, const std::string& field) {
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << field;
  EXPECT_NE(status.error_message().find(field), std::string::npos) << status.error_message();
  std::optional<semnav::common::v1::ErrorInfo> info =
      GetDetail<semnav::common::v1::ErrorInfo>(status);
  ASSERT_TRUE(info.has_value()) << field;
  EXPECT_EQ(info->field(), field);
}

// A contact (where the robot touched something the grid lacks) is an obstacle for that call
// alone: the path goes round it, and the next call without it goes straight again.
TEST_F(PlanningContract, AContactIsAnObstacleForThatCallOnly) {
  const std::vector<std::string> open_rows = {".......", ".......", ".......", ".......",
                                              "......."};
  pb::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = MakeGrid(open_rows, 0.5);
  *request.mutable_start() = At(0, 2, 0.5);
  *request.mutable_goal() = At(6, 2, 0.5);
  pb::PlanPathResponse straight;
  ASSERT_TRUE(Plan(request, &straight).ok());
  EXPECT_NEAR(straight.length_m(), 3.0, 1e-9);

  pb::PlanPathRequest touched = request;
  *touched.add_contacts() = At(3, 2, 0.5);  // cell (3, 2), on the straight line
  pb::PlanPathResponse around;
  const grpc::Status status = Plan(touched, &around);
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_GT(around.length_m(), 3.0 + 0.1);
  for (const auto& p : around.path()) {
    EXPECT_FALSE(std::abs(p.x() - At(3, 2, 0.5).x()) < 0.25 &&
                 std::abs(p.y() - At(3, 2, 0.5).y()) < 0.25)
        << p.x() << ", " << p.y();
  }
  // A contact outside the grid changes nothing.
  pb::PlanPathRequest outside = request;
  outside.add_contacts()->set_x(50.0);
  pb::PlanPathResponse same;
  ASSERT_TRUE(Plan(outside, &same).ok());
  EXPECT_NEAR(same.length_m(), 3.0, 1e-9);

  pb::PlanPathResponse again;
  ASSERT_TRUE(Plan(request, &again).ok());
  EXPECT_NEAR(again.length_m(), 3.0, 1e-9);
}

TEST_F(PlanningContract, BadInputNamesTheFieldAndChangesNothing) {
  pb::PlanPathResponse before;
  ASSERT_TRUE(Plan(DoorRequest(pb::PLANNER_KIND_JPS), &before).ok());

  pb::PlanPathResponse response;
  pb::PlanPathRequest outside = DoorRequest(pb::PLANNER_KIND_JPS);
  outside.mutable_goal()->set_x(100.0);  // far beyond max_goal_outside_m
  ExpectFieldError(Plan(outside, &response), "goal");

  pb::PlanPathRequest short_layer = DoorRequest(pb::PLANNER_KIND_JPS);
  short_layer.mutable_source()->mutable_grid()->mutable_layers(0)->mutable_data()->pop_back();
  ExpectFieldError(Plan(short_layer, &response), "source.grid.layers[0].data");

  pb::PlanPathRequest no_grid = DoorRequest(pb::PLANNER_KIND_JPS);
  no_grid.clear_source();
  ExpectFieldError(Plan(no_grid, &response), "source");

  pb::PlanPathRequest bad_radius = DoorRequest(pb::PLANNER_KIND_JPS);
  bad_radius.set_robot_radius_m(-1.0);
  ExpectFieldError(Plan(bad_radius, &response), "robot_radius_m");

  pb::PlanPathRequest bad_beta = WallRequest(-2.0);
  ExpectFieldError(Plan(bad_beta, &response), "multimodal.beta");

  pb::PlanPathRequest no_sighting = DoorRequest(pb::PLANNER_KIND_JPS);
  no_sighting.set_allow_alternative_point(true);
  ExpectFieldError(Plan(no_sighting, &response), "first_sighting");

  pb::PlanPathRequest zero_resolution = DoorRequest(pb::PLANNER_KIND_JPS);
  zero_resolution.mutable_source()->mutable_grid()->set_resolution(0.0);
  ExpectFieldError(Plan(zero_resolution, &response), "source.grid.resolution");
  // Finite but below 1 mm: metre-sized settings in cells would overflow (fuzzer input).
  pb::PlanPathRequest tiny_resolution = DoorRequest(pb::PLANNER_KIND_JPS);
  tiny_resolution.mutable_source()->mutable_grid()->set_resolution(1e-300);
  ExpectFieldError(Plan(tiny_resolution, &response), "source.grid.resolution");
  // Checked before any fetch: this planning has no mapping service to ask.
  pb::PlanPathRequest stale = DoorRequest(pb::PLANNER_KIND_JPS);
  stale.mutable_source()->mutable_live_map()->set_max_age_ms(10001);
  ExpectFieldError(Plan(stale, &response), "source.live_map.max_age_ms");

  pb::PlanPathRequest nan_contact = DoorRequest(pb::PLANNER_KIND_JPS);
  *nan_contact.add_contacts() = At(1, 1, 0.5);
  nan_contact.add_contacts()->set_y(std::nan(""));
  ExpectFieldError(Plan(nan_contact, &response), "contacts[1].y");
  pb::PlanPathRequest many_contacts = DoorRequest(pb::PLANNER_KIND_JPS);
  for (int i = 0; i < 33; ++i) *many_contacts.add_contacts() = At(1, 1, 0.5);
  ExpectFieldError(Plan(many_contacts, &response), "contacts");

  // The service still answers, and the same request gives the same plan.
  pb::PlanPathResponse after;
  ASSERT_TRUE(Plan(DoorRequest(pb::PLANNER_KIND_JPS), &after).ok());
  EXPECT_EQ(after.path_size(), before.path_size());
  EXPECT_DOUBLE_EQ(after.length_m(), before.length_m());
}

}  // namespace
}  // namespace semnav::planning
