// PlanningClient's exploration requests against an in-process PlanningService that records them:
// the task's strategy and semantic context arrive as planning's SemanticContext, EROI values come
// with their live-map window, and a refused value grid is retried with uniform values.
#include "services/reasoning/server/planning_client.h"

#include <grpcpp/grpcpp.h>

#include "absl/synchronization/mutex.h"
#include "gtest/gtest.h"
#include "services/common/status/grpc_status.h"
#include "services/reasoning/server/proto_convert.h"

namespace semnav::reasoning {
namespace {

namespace pb = ::semnav::planning::v1;

class RecordingPlanning final : public pb::PlanningService::Service {
 public:
  grpc::Status PlanPath(grpc::ServerContext*, const pb::PlanPathRequest* request,
                        pb::PlanPathResponse* response) override {
    absl::MutexLock lock(&mu);
    radii.push_back(request->robot_radius_m());
    contact_counts.push_back(request->contacts_size());
    tolerances.push_back(request->goal_tolerance_m());
    path_max_ages_ms.push_back(request->source().live_map().max_age_ms());
    if (request->robot_radius_m() > no_path_above_m ||
        (no_path_with_contacts && request->contacts_size() > 0)) {
      absl::Status no_path = absl::NotFoundError("goal is not reachable from start");
      pb::PlanFailureDetail detail;
      detail.set_reason(pb::PLAN_FAILURE_REASON_NO_PATH);
      AttachDetail(no_path, detail);
      return ToGrpcStatus(no_path);
    }
    if (failure.ok()) {
      if (request->robot_radius_m() > detour_above_m) {
        for (const auto& [x, y] : detour) {
          common::v1::Pose2D* point = response->add_path();
          point->set_x(x);
          point->set_y(y);
        }
      }
      *response->add_path() = request->goal();
    }
    return failure;
  }
  grpc::Status SelectExplorationGoal(grpc::ServerContext*,
                                     const pb::SelectExplorationGoalRequest* request,
                                     pb::SelectExplorationGoalResponse* response) override {
    absl::MutexLock lock(&mu);
    requests.push_back(*request);
    if (!failure.ok()) return failure;
    if (refuse_values && request->eroi_semantic_values_size() > 0) {
      return grpc::Status(grpc::StatusCode::INVALID_ARGUMENT,
                          "eroi_semantic_values has 2 values; this grid has 6");
    }
    response->mutable_goal()->set_x(4.0);
    response->mutable_goal()->set_y(-1.0);
    return grpc::Status::OK;
  }
  absl::Mutex mu;
  bool refuse_values = false;
  grpc::Status failure;  // every answer's (PlanPath answers OK with the goal as its path otherwise)
  double no_path_above_m = 1e9;  // PlanPath: NO_PATH for a robot_radius_m above this
  double detour_above_m = 1e9;   // PlanPath: for a robot_radius_m above this, by `detour` first
  std::vector<std::pair<double, double>> detour;
  bool no_path_with_contacts = false;      // PlanPath: NO_PATH for any request with contacts
  std::vector<int> contact_counts;         // PlanPath's contacts_size(), in call order
  std::vector<double> radii;               // PlanPath's robot_radius_m, in call order
  std::vector<double> tolerances;          // PlanPath's goal_tolerance_m, in call order
  std::vector<uint32_t> path_max_ages_ms;  // PlanPath's source.live_map.max_age_ms, in call order
  std::vector<pb::SelectExplorationGoalRequest> requests;
};

class GatewayPlanningClientTest : public ::testing::Test {
 protected:
  void SetUp() override {
    grpc::ServerBuilder builder;
    int port = 0;
    builder.AddListeningPort("127.0.0.1:0", grpc::InsecureServerCredentials(), &port);
    builder.RegisterService(&planning_);
    server_ = builder.BuildAndStart();
    auto channel = grpc::CreateChannel("127.0.0.1:" + std::to_string(port),
                                       grpc::InsecureChannelCredentials());
    ASSERT_TRUE(
        channel->WaitForConnected(std::chrono::system_clock::now() + std::chrono::seconds(5)));
    const PlanningSettings settings;  // SEMANTIC_FRONTIER by default, 2 s deadline
    client_channel_ = channel;
    client_ = std::make_unique<PlanningClient>(channel, settings);
  }
  void TearDown() override { server_->Shutdown(); }

  RecordingPlanning planning_;
  std::unique_ptr<grpc::Server> server_;
  std::shared_ptr<grpc::Channel> client_channel_;
  std::unique_ptr<PlanningClient> client_;
};

TEST_F(GatewayPlanningClientTest, SemanticContextAndTaskStrategyReachPlanning) {
  ExplorationContext context;
  context.objects.push_back({"sink", Eigen::Vector3d(2.0, 3.0, 0.9), 0.0, 0.0, 0.42});
  context.objects.push_back({"dining table", Eigen::Vector3d(-1.0, 0.5, 0.7), 0.5, 1.0, 0.0});
  context.visited.push_back(Eigen::Vector3d(0.0, 0.0, 0.0));
  RobotPose pose;
  pose.position = Eigen::Vector3d(1.0, 2.0, 0.3);
  const ExplorationQuery query{
      pose, {Eigen::Vector3d(5.0, 6.0, 0.3)}, 1.5, RobotPlatform::kGround, {}, 0.0};
  absl::StatusOr<Eigen::Vector3d> goal =
      client_->SelectGoal(query, ExplorationStrategy::kCoverageMax, context);
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(4.0, -1.0, 0.3)));  // z stays the robot's

  absl::MutexLock lock(&planning_.mu);
  ASSERT_EQ(planning_.requests.size(), 1u);
  const pb::SelectExplorationGoalRequest& request = planning_.requests[0];
  EXPECT_EQ(request.strategy(), pb::EXPLORATION_STRATEGY_COVERAGE_MAX);
  EXPECT_EQ(request.platform(), pb::EXPLORATION_PLATFORM_GROUND);
  ASSERT_EQ(request.excluded_goals_size(),
            1);  // spent goals reach planning with the task's context
  EXPECT_EQ(request.excluded_goals(0).x(), 5.0);
  EXPECT_EQ(request.excluded_goals(0).y(), 6.0);
  EXPECT_EQ(request.excluded_radius_m(), 1.5);
  EXPECT_FALSE(request.has_keep_goal());
  ASSERT_EQ(request.semantics().objects_size(), 2);
  EXPECT_EQ(request.semantics().objects(0).label(), "sink");
  EXPECT_DOUBLE_EQ(request.semantics().objects(0).position().y(), 3.0);
  EXPECT_DOUBLE_EQ(request.semantics().objects(0).cooccurrence(), 0.42);
  EXPECT_DOUBLE_EQ(request.semantics().objects(1).relevance(), 0.5);
  EXPECT_DOUBLE_EQ(request.semantics().objects(1).relation(), 1.0);
  ASSERT_EQ(request.semantics().visited_size(), 1);
  EXPECT_FALSE(request.source().live_map().has_window_min());  // the whole live map
  EXPECT_EQ(request.eroi_semantic_values_size(), 0);           // values only for EROI_UTILITY
  EXPECT_FALSE(request.has_search_area());                     // none given: the whole map
}

TEST_F(GatewayPlanningClientTest, SearchAreaReachesPlanning) {
  ExplorationContext context;
  context.search_area = SearchArea{Eigen::Vector2d(-1.0, -2.0), Eigen::Vector2d(44.0, 46.0)};
  ASSERT_TRUE(client_->SelectGoal(ExplorationQuery{}, std::nullopt, context).ok());
  absl::MutexLock lock(&planning_.mu);
  ASSERT_EQ(planning_.requests.size(), 1u);
  const pb::SearchArea& area = planning_.requests[0].search_area();
  EXPECT_EQ(area.min_x(), -1.0);
  EXPECT_EQ(area.min_y(), -2.0);
  EXPECT_EQ(area.max_x(), 44.0);
  EXPECT_EQ(area.max_y(), 46.0);
}

TEST_F(GatewayPlanningClientTest, EroiValuesComeWithTheirWindowAndARefusedGridIsRetriedUniform) {
  ExplorationContext context;
  context.eroi_values = {0.25, 0.75};
  context.eroi_window_min = Eigen::Vector2d(-1.0, -1.0);
  context.eroi_window_max = Eigen::Vector2d(3.0, 1.0);
  context.eroi_edge_m = 2.0;
  ASSERT_TRUE(client_->SelectGoal({}, ExplorationStrategy::kEroiUtility, context).ok());
  {
    absl::MutexLock lock(&planning_.mu);
    const pb::SelectExplorationGoalRequest& request = planning_.requests.back();
    ASSERT_EQ(request.eroi_semantic_values_size(), 2);
    EXPECT_DOUBLE_EQ(request.eroi_semantic_values(1), 0.75);
    EXPECT_DOUBLE_EQ(request.source().live_map().window_min().x(), -1.0);
    EXPECT_DOUBLE_EQ(request.source().live_map().window_max().x(), 2.5);  // pulled in by edge / 4
    EXPECT_DOUBLE_EQ(request.source().live_map().window_max().y(), 0.5);
    planning_.refuse_values = true;
  }
  ASSERT_TRUE(client_->SelectGoal({}, ExplorationStrategy::kEroiUtility, context).ok());
  absl::MutexLock lock(&planning_.mu);
  ASSERT_EQ(planning_.requests.size(), 3u);  // refused, then asked again without values
  EXPECT_EQ(planning_.requests[2].eroi_semantic_values_size(), 0);
  EXPECT_FALSE(planning_.requests[2].source().live_map().has_window_min());
}

// On the way to a goal the executor asks again with the goal to keep: the frontier strategies
// get it; COVERAGE_MAX and EROI_UTILITY, which have no frontier to see cleared, keep it without
// a call.
TEST_F(GatewayPlanningClientTest, TheGoalToKeepReachesTheFrontierStrategiesOnly) {
  RobotPose pose;
  pose.position = Eigen::Vector3d(1.0, 2.0, 0.3);
  const ExplorationQuery query{
      pose, {}, 1.0, RobotPlatform::kGround, Eigen::Vector3d(7.0, -2.0, 0.3), 0.75};
  absl::StatusOr<Eigen::Vector3d> goal =
      client_->SelectGoal(query, ExplorationStrategy::kSemanticFrontier, ExplorationContext{});
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(4.0, -1.0, 0.3)));  // planning's answer
  for (const ExplorationStrategy kept :
       {ExplorationStrategy::kCoverageMax, ExplorationStrategy::kEroiUtility}) {
    goal = client_->SelectGoal(query, kept, ExplorationContext{});
    ASSERT_TRUE(goal.ok()) << goal.status();
    EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(7.0, -2.0, 0.3)));
  }
  absl::MutexLock lock(&planning_.mu);
  ASSERT_EQ(planning_.requests.size(), 1u);
  EXPECT_EQ(planning_.requests[0].strategy(), pb::EXPLORATION_STRATEGY_SEMANTIC_FRONTIER);
  EXPECT_EQ(planning_.requests[0].keep_goal().x(), 7.0);
  EXPECT_EQ(planning_.requests[0].keep_goal().y(), -2.0);
  EXPECT_EQ(planning_.requests[0].keep_radius_m(), 0.75);
}

// A look at a sighting goes to planning even with a goal to keep (EROI_UTILITY keeps its goal
// without a call otherwise), over the whole live map (no EROI window or values), with the
// sighting and the distance and no goal to keep.
TEST_F(GatewayPlanningClientTest, ALookAtASightingAlwaysAsksPlanningOverTheWholeMap) {
  RobotPose pose;
  pose.position = Eigen::Vector3d(1.0, 2.0, 1.5);
  const ExplorationQuery query{
      pose, {}, 1.0, RobotPlatform::kAerial, Eigen::Vector3d(7.0, -2.0, 1.5), 0.75};
  ExplorationContext context;
  context.eroi_values = {0.25, 0.75};
  context.eroi_window_min = Eigen::Vector2d(-1.0, -1.0);
  context.eroi_window_max = Eigen::Vector2d(3.0, 1.0);
  context.eroi_edge_m = 2.0;
  context.look_at = Eigen::Vector3d(9.0, 5.0, 0.0);
  context.look_distance_m = 3.0;
  absl::StatusOr<Eigen::Vector3d> goal =
      client_->SelectGoal(query, ExplorationStrategy::kEroiUtility, context);
  ASSERT_TRUE(goal.ok()) << goal.status();
  EXPECT_TRUE(goal->isApprox(Eigen::Vector3d(4.0, -1.0, 1.5)));  // planning's answer
  absl::MutexLock lock(&planning_.mu);
  ASSERT_EQ(planning_.requests.size(), 1u);
  const pb::SelectExplorationGoalRequest& request = planning_.requests[0];
  EXPECT_EQ(request.look_at().x(), 9.0);
  EXPECT_EQ(request.look_at().y(), 5.0);
  EXPECT_EQ(request.look_distance_m(), 3.0);
  EXPECT_FALSE(request.has_keep_goal());
  EXPECT_EQ(request.eroi_semantic_values_size(), 0);
  EXPECT_FALSE(request.source().live_map().has_window_min());
}

// Issue "Fleet and faults": planning or mapping gone is UNAVAILABLE naming it, so the task
// pauses; it used to be an empty path (robot-local planning) and NOT_FOUND (a blind step).
TEST_F(GatewayPlanningClientTest, PlanningOrMappingGoneIsUnavailableNamingIt) {
  const PathQuery path{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), false, 0.0, 0.0, std::nullopt};
  const ExplorationQuery explore{RobotPose{}, {}, 1.0, RobotPlatform::kUnspecified, {}, 0.0};
  const auto answer = [&](grpc::Status failure) {
    absl::MutexLock lock(&planning_.mu);
    planning_.failure = std::move(failure);
  };
  answer(grpc::Status(grpc::StatusCode::UNAVAILABLE,
                      "source.live_map: mapping service GetGridMap failed: failed to connect"));
  absl::StatusOr<std::vector<Eigen::Vector3d>> planned = client_->Plan(path);
  EXPECT_TRUE(absl::IsUnavailable(planned.status())) << planned.status();
  EXPECT_EQ(UnavailableDependency(planned.status()), "mapping");
  absl::StatusOr<Eigen::Vector3d> goal = client_->ExplorationGoal(explore);
  EXPECT_TRUE(absl::IsUnavailable(goal.status())) << goal.status();
  EXPECT_EQ(UnavailableDependency(goal.status()), "mapping");

  for (const grpc::StatusCode code :
       {grpc::StatusCode::UNAVAILABLE, grpc::StatusCode::DEADLINE_EXCEEDED}) {
    answer(grpc::Status(code, "overloaded"));
    planned = client_->Plan(path);
    EXPECT_TRUE(absl::IsUnavailable(planned.status())) << planned.status();
    EXPECT_EQ(UnavailableDependency(planned.status()), "planning");
    goal = client_->ExplorationGoal(explore);
    EXPECT_TRUE(absl::IsUnavailable(goal.status())) << goal.status();
  }

  // Planning up but without an answer for this query: the robot still plans locally.
  answer(grpc::Status(grpc::StatusCode::FAILED_PRECONDITION, "no map yet"));
  planned = client_->Plan(path);
  ASSERT_TRUE(planned.ok()) << planned.status();
  EXPECT_TRUE(planned->empty());  // the robot plans locally
  EXPECT_TRUE(absl::IsNotFound(client_->ExplorationGoal(explore).status()));

  server_->Shutdown();  // gone: the channel is not READY
  server_->Wait();
  planned = client_->Plan(path);
  EXPECT_TRUE(absl::IsUnavailable(planned.status())) << planned.status();
  EXPECT_EQ(UnavailableDependency(planned.status()), "planning");
  EXPECT_TRUE(absl::IsUnavailable(client_->ExplorationGoal(explore).status()));
}

// Regression (hand-drawn office_kitchenette, start 2): pressed against a wall after a collision,
// the robot's footprint plus clearance cut its cell off from every goal (NO_PATH), and it spent
// the episode looking around in the corner. With the bare footprint it has a way out.
TEST_F(GatewayPlanningClientTest, NoPathWithTheClearanceIsRetriedWithTheBareFootprint) {
  {
    absl::MutexLock lock(&planning_.mu);
    planning_.no_path_above_m = 0.3;
  }
  const PathQuery query{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), false, 0.25, 0.15, std::nullopt};
  absl::StatusOr<std::vector<Eigen::Vector3d>> planned = client_->Plan(query);
  ASSERT_TRUE(planned.ok()) << planned.status();
  ASSERT_EQ(planned->size(), 1u);
  EXPECT_DOUBLE_EQ(planned->back().x(), 3.0);
  {
    absl::MutexLock lock(&planning_.mu);
    EXPECT_EQ(planning_.radii, (std::vector<double>{0.4, 0.25}));
    planning_.radii.clear();
    planning_.no_path_above_m = 0.0;
  }
  // No path even for the bare footprint: NOT_FOUND, after the same two attempts.
  EXPECT_TRUE(absl::IsNotFound(client_->Plan(query).status()));
  absl::MutexLock lock(&planning_.mu);
  EXPECT_EQ(planning_.radii.size(), 2u);
}

// Contacts reach planning; when they leave no way (one where the robot brushed a door frame), the
// way is planned without them, with the clearance and then the bare footprint.
TEST_F(GatewayPlanningClientTest, ContactsReachPlanningAndAWayTheyCloseIsPlannedWithoutThem) {
  PathQuery query{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), false, 0.25, 0.15, std::nullopt};
  query.contacts = {Eigen::Vector3d(0.3, 0, 0), Eigen::Vector3d(0.3, 0.1, 0)};
  ASSERT_TRUE(client_->Plan(query).ok());
  {
    absl::MutexLock lock(&planning_.mu);
    EXPECT_EQ(planning_.contact_counts, (std::vector<int>{2}));
    planning_.contact_counts.clear();
    planning_.radii.clear();
    planning_.no_path_with_contacts = true;
  }
  absl::StatusOr<std::vector<Eigen::Vector3d>> planned = client_->Plan(query);
  ASSERT_TRUE(planned.ok()) << planned.status();
  EXPECT_DOUBLE_EQ(planned->back().x(), 3.0);
  {
    absl::MutexLock lock(&planning_.mu);
    // With contacts: clearance, bare footprint; without: clearance (a way).
    EXPECT_EQ(planning_.contact_counts, (std::vector<int>{2, 2, 0}));
    EXPECT_EQ(planning_.radii, (std::vector<double>{0.4, 0.25, 0.4}));
  }
}

// Regression (FR-079 start 1): with the clearance the way to a trash can 5.6 m west ran 63
// waypoints east through rooms the robot had not seen, past a pillar the footprint alone clears;
// the robot drove 16 m the wrong way. A way much longer than the straight line is planned again
// with the bare footprint, whose way is taken when it is much shorter; a way only a little longer
// is kept without a second call.
TEST_F(GatewayPlanningClientTest, ALongWayRoundForTheClearanceGivesWayToTheBareFootprints) {
  const PathQuery query{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), false, 0.25, 0.15, std::nullopt};
  {
    absl::MutexLock lock(&planning_.mu);
    planning_.detour_above_m = 0.3;
    planning_.detour = {{0, 10}, {3, 10}};  // 23 m against 3 m straight
  }
  absl::StatusOr<std::vector<Eigen::Vector3d>> planned = client_->Plan(query);
  ASSERT_TRUE(planned.ok()) << planned.status();
  ASSERT_EQ(planned->size(), 1u);  // the bare footprint's straight way
  EXPECT_DOUBLE_EQ(planned->back().x(), 3.0);
  {
    absl::MutexLock lock(&planning_.mu);
    EXPECT_EQ(planning_.radii, (std::vector<double>{0.4, 0.25}));
    planning_.radii.clear();
    planning_.detour = {{1.5, 1.0}};  // 3.6 m: a little longer than 3 m, kept
  }
  planned = client_->Plan(query);
  ASSERT_TRUE(planned.ok()) << planned.status();
  EXPECT_EQ(planned->size(), 2u);
  {
    absl::MutexLock lock(&planning_.mu);
    EXPECT_EQ(planning_.radii, (std::vector<double>{0.4}));
    planning_.radii.clear();
    planning_.detour = {{0, 10}, {3, 10}};
  }
  // Off (factor 0): the clearance's way, however long.
  PlanningSettings off;
  off.clearance_detour_factor = 0.0;
  PlanningClient keeps_clearance(client_channel_, off);
  planned = keeps_clearance.Plan(query);
  ASSERT_TRUE(planned.ok()) << planned.status();
  EXPECT_EQ(planned->size(), 3u);
  absl::MutexLock lock(&planning_.mu);
  EXPECT_EQ(planning_.radii, (std::vector<double>{0.4}));
}

// The executor's approach asks for the free point nearest an object within reach: the query's
// tolerance goes to planning in place of the configured one (0 here), and only for that query.
TEST_F(GatewayPlanningClientTest, AQuerysGoalToleranceReachesPlanning) {
  PathQuery query{
      Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), false, 0.25, 0.0, std::nullopt};
  ASSERT_TRUE(client_->Plan(query).ok());
  query.goal_tolerance_m = 1.1;
  ASSERT_TRUE(client_->Plan(query).ok());
  absl::MutexLock lock(&planning_.mu);
  EXPECT_EQ(planning_.tolerances, (std::vector<double>{0.0, 1.1}));
}

TEST_F(GatewayPlanningClientTest, TheAcceptedLiveMapAgeReachesPlanning) {
  PathQuery path{Eigen::Vector3d::Zero(), Eigen::Vector3d(3, 0, 0), false, 0.0, 0.0, std::nullopt};
  ExplorationQuery explore{RobotPose{}, {}, 1.0, RobotPlatform::kGround, std::nullopt, 0.0};
  ASSERT_TRUE(client_->Plan(path).ok());
  ASSERT_TRUE(client_->ExplorationGoal(explore).ok());
  path.live_map_max_age_ms = 500;
  explore.live_map_max_age_ms = 250;
  ASSERT_TRUE(client_->Plan(path).ok());
  ASSERT_TRUE(client_->ExplorationGoal(explore).ok());
  absl::MutexLock lock(&planning_.mu);
  EXPECT_EQ(planning_.path_max_ages_ms, (std::vector<uint32_t>{0, 500}));
  ASSERT_EQ(planning_.requests.size(), 2u);
  EXPECT_TRUE(planning_.requests[0].source().has_live_map());
  EXPECT_EQ(planning_.requests[0].source().live_map().max_age_ms(), 0u);
  EXPECT_EQ(planning_.requests[1].source().live_map().max_age_ms(), 250u);
}

pb::PlanPathResponse FlyOverCrate() {
  pb::PlanPathResponse response;
  for (double x : {0.0, 1.0, 2.0, 3.0}) {
    common::v1::Pose2D* p = response.add_path();
    p->set_x(x);
    p->set_y(0.5);
  }
  auto segment = [&](uint32_t first, uint32_t last, pb::MotionMode mode, double altitude) {
    pb::PathSegment* s = response.add_segments();
    s->set_first_point(first);
    s->set_last_point(last);
    s->set_mode(mode);
    s->set_altitude_m(altitude);
  };
  segment(0, 1, pb::MOTION_MODE_ROLLING, 0.0);
  segment(1, 2, pb::MOTION_MODE_FLYING, 1.4);
  segment(2, 3, pb::MOTION_MODE_ROLLING, 0.0);
  return response;
}

// Regression (flyroll_01/02: "robot blocked: collision with crate"): the gateway dropped the
// segments of JUMP_ASTAR's answer and sent every point at the goal's z, so the fly-roll robot
// rolled into each crate its path flew over. Now it climbs straight up where the flight begins,
// flies at the segment's altitude and lands straight down where rolling resumes.
TEST(GatewayRobotPath, FlyingSegmentsClimbFlyAndLand) {
  PathQuery query;
  query.goal = Eigen::Vector3d(3, 0.5, 0.7);  // an object's height: not where the robot drives
  query.multi_modal = true;
  const std::vector<Eigen::Vector3d> path = RobotPath(FlyOverCrate(), query);
  const std::vector<Eigen::Vector3d> expected = {{0, 0.5, 0},   {1, 0.5, 0}, {1, 0.5, 1.4},
                                                 {2, 0.5, 1.4}, {2, 0.5, 0}, {3, 0.5, 0}};
  ASSERT_EQ(path.size(), expected.size());
  for (size_t i = 0; i < path.size(); ++i)
    EXPECT_TRUE(path[i].isApprox(expected[i])) << i << ": " << path[i].transpose();
  // The robot's modes: the climb, the flight and the landing are flown.
  api::NavigateAction navigate;
  for (const Eigen::Vector3d& p : path) {
    common::v1::Vector3* v = navigate.add_path()->mutable_position();
    v->set_x(p.x());
    v->set_y(p.y());
    v->set_z(p.z());
  }
  SetFlyRollModes(&navigate);
  const std::vector<api::LocomotionMode> modes = {
      api::LOCOMOTION_MODE_GROUND, api::LOCOMOTION_MODE_GROUND, api::LOCOMOTION_MODE_AIR,
      api::LOCOMOTION_MODE_AIR,    api::LOCOMOTION_MODE_AIR,    api::LOCOMOTION_MODE_GROUND};
  for (int i = 0; i < navigate.path_size(); ++i) EXPECT_EQ(navigate.path(i).mode(), modes[i]) << i;
}

TEST(GatewayRobotPath, AHoveringRobotLandsFirstAndTwoDimensionalPathsKeepTheGoalHeight) {
  PathQuery query;
  query.start = Eigen::Vector3d(0, 0.5, 1.4);  // still in the air after a flight
  query.goal = Eigen::Vector3d(3, 0.5, 0.7);
  query.multi_modal = true;
  pb::PlanPathResponse rolling = FlyOverCrate();
  rolling.mutable_segments()->Clear();
  pb::PathSegment* s = rolling.add_segments();
  s->set_first_point(0);
  s->set_last_point(3);
  s->set_mode(pb::MOTION_MODE_ROLLING);
  std::vector<Eigen::Vector3d> path = RobotPath(rolling, query);
  ASSERT_EQ(path.size(), 5u);
  EXPECT_TRUE(path[0].isApprox(Eigen::Vector3d(0, 0.5, 1.4)));
  EXPECT_TRUE(path[1].isApprox(Eigen::Vector3d(0, 0.5, 0)));  // straight down
  EXPECT_TRUE(path[4].isApprox(Eigen::Vector3d(3, 0.5, 0)));
  query.multi_modal = false;
  path = RobotPath(rolling, query);
  ASSERT_EQ(path.size(), 4u);
  for (const Eigen::Vector3d& p : path) EXPECT_DOUBLE_EQ(p.z(), 0.7);
}

}  // namespace
}  // namespace semnav::reasoning
