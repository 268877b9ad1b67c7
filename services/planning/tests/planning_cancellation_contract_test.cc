// Contract test: deadlines and cancellation of PlanPath over gRPC, on a
// real semnav-planning binary with one search worker, so a search that did
// not stop would visibly hold up the next call.
#include <grpcpp/client_context.h>
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/common/status/grpc_status.h"
#include "tests/support/service_process.h"

namespace semnav::planning {
namespace {

namespace pb = semnav::planning::v1;
using semnav::common::v1::GridMap;
using Clock = std::chrono::steady_clock;

// One worker; a search cap far beyond the test, so only the deadline or a
// cancel can stop a search; a generous reply margin for a loaded CI machine.
class PlanningCancellation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string config = ::testing::TempDir() + "/planning_cancellation.yaml";
    std::ofstream(config) << "planning:\n  worker_threads: 1\n  max_planning_time_ms: 600000\n"
                             "  deadline_margin_ms: 500\n";
    absl::StatusOr<std::unique_ptr<testing::ServiceProcess>> started =
        testing::ServiceProcess::Start("semnav-planning", {"--config", config});
    ASSERT_TRUE(started.ok()) << started.status();
    process_ = std::move(*started);
  }
  static void TearDownTestSuite() { process_.reset(); }

  static std::unique_ptr<pb::PlanningService::Stub> Stub() {
    return pb::PlanningService::NewStub(process_->channel());
  }

 private:
  static inline std::unique_ptr<testing::ServiceProcess> process_;
};

// A free HIERARCHICAL grid of 5 cm cells with the goal walled off by
// structure in its corner: A* floods every other cell before NO_PATH
// (seconds at 2000 x 1500 cells).
pb::PlanPathRequest HopelessRequest() {
  constexpr int kWidth = 2000;
  constexpr int kHeight = 1500;
  GridMap grid;
  grid.set_resolution(0.05);
  grid.set_width(kWidth);
  grid.set_height(kHeight);
  std::string data(static_cast<size_t>(kWidth) * kHeight, '\0');
  for (int i = 0; i < 3; ++i) {
    data[static_cast<size_t>(kHeight - 3) * kWidth + kWidth - 3 + i] = 100;  // row below
    data[static_cast<size_t>(kHeight - 3 + i) * kWidth + kWidth - 3] = 100;  // column left
  }
  auto* layer = grid.add_layers();
  layer->set_kind(semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  layer->set_data(std::move(data));
  pb::PlanPathRequest request;
  *request.mutable_source()->mutable_grid() = std::move(grid);
  request.mutable_start()->set_x(0.025);
  request.mutable_start()->set_y(0.025);
  request.mutable_goal()->set_x((kWidth - 1) * 0.05 + 0.025);
  request.mutable_goal()->set_y((kHeight - 1) * 0.05 + 0.025);
  request.set_planner(pb::PLANNER_KIND_ASTAR);
  return request;
}

// A 3 x 1 free corridor: answers at once.
pb::PlanPathRequest QuickRequest() {
  pb::PlanPathRequest request;
  GridMap* grid = request.mutable_source()->mutable_grid();
  grid->set_resolution(1.0);
  grid->set_width(3);
  grid->set_height(1);
  auto* layer = grid->add_layers();
  layer->set_kind(semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL);
  layer->set_data(std::string(3, '\0'));
  request.mutable_start()->set_x(0.5);
  request.mutable_goal()->set_x(2.5);
  return request;
}

// Wall milliseconds of a QuickRequest, which must succeed.
double QuickCallMs(pb::PlanningService::Stub& stub) {
  const Clock::time_point t0 = Clock::now();
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(60));
  pb::PlanPathResponse response;
  const grpc::Status status = stub.PlanPath(&context, QuickRequest(), &response);
  EXPECT_TRUE(status.ok()) << status.error_message();
  EXPECT_DOUBLE_EQ(response.length_m(), 2.0);
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Wall milliseconds of one HopelessRequest run to its end (NO_PATH), measured once. A worker still
// busy with a search it was told to drop would hold the next call about this long, so the tests
// compare with it instead of a fixed bound: both stretch alike on a loaded machine.
double HopelessSearchMs(pb::PlanningService::Stub& stub) {
  static const double ms = [&] {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(300));
    pb::PlanPathResponse response;
    const Clock::time_point t0 = Clock::now();
    const grpc::Status status = stub.PlanPath(&context, HopelessRequest(), &response);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND) << status.error_message();
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  }();
  return ms;
}

TEST_F(PlanningCancellation, CallDeadlineGivesTypedTimeoutAndFreesTheWorker) {
  auto stub = Stub();
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::milliseconds(1200));
  pb::PlanPathResponse response;
  const Clock::time_point t0 = Clock::now();
  const grpc::Status status = stub->PlanPath(&context, HopelessRequest(), &response);
  const double elapsed_ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
  EXPECT_EQ(status.error_code(), grpc::StatusCode::DEADLINE_EXCEEDED) << status.error_message();
  // The server stopped the search itself (deadline - margin) and said why.
  std::optional<pb::PlanFailureDetail> detail = GetDetail<pb::PlanFailureDetail>(status);
  ASSERT_TRUE(detail.has_value()) << "no typed detail after " << elapsed_ms
                                  << " ms: " << status.error_message();
  EXPECT_EQ(detail->reason(), pb::PLAN_FAILURE_REASON_TIMEOUT);
  EXPECT_LT(elapsed_ms, 1200.0);
  // The only worker is free again at once: far sooner than a search left running would free it.
  const double quick_ms = QuickCallMs(*stub);  // before the comparison's own search
  EXPECT_LT(quick_ms, HopelessSearchMs(*stub) / 2);
}

TEST_F(PlanningCancellation, CancelledSearchesStopAndTheServiceKeepsServing) {
  // Three hopeless searches for one worker: running to the end they would
  // hold it for several seconds each.
  constexpr int kCalls = 3;
  std::vector<std::unique_ptr<grpc::ClientContext>> contexts;
  std::vector<grpc::Status> statuses(kCalls);
  std::vector<std::thread> callers;
  const pb::PlanPathRequest hopeless = HopelessRequest();
  for (int i = 0; i < kCalls; ++i) {
    contexts.push_back(std::make_unique<grpc::ClientContext>());
    callers.emplace_back([&, i] {
      auto stub = Stub();
      pb::PlanPathResponse response;
      statuses[i] = stub->PlanPath(contexts[i].get(), hopeless, &response);
    });
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // the first one is searching
  for (auto& context : contexts) context->TryCancel();
  for (std::thread& caller : callers) caller.join();
  for (const grpc::Status& status : statuses) {
    // A cancelled call gets no reply from the server, so CANCELLED is all
    // the caller can see; the worker being free shows the search stopped.
    EXPECT_EQ(status.error_code(), grpc::StatusCode::CANCELLED) << status.error_message();
  }
  auto stub = Stub();
  const double quick_ms = QuickCallMs(*stub);  // before the comparison's own search
  EXPECT_LT(quick_ms, HopelessSearchMs(*stub) / 2);
}

}  // namespace
}  // namespace semnav::planning
