// Contract test across two real binaries: semnav-mapping builds a map from
// rendered frames; semnav-planning fetches it by live_map and plans on it.
#include <grpcpp/client_context.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>

#include "absl/time/clock.h"
#include "semnav/mapping/v1/mapping_service.grpc.pb.h"
#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "services/mapping/testing/frame_proto.h"
#include "services/mapping/testing/synthetic_room.h"
#include "tests/support/service_process.h"

namespace semnav::planning {
namespace {

namespace mpb = semnav::mapping::v1;
namespace pb = semnav::planning::v1;
using semnav::common::v1::GridMap;

// Centre of the free HIERARCHICAL cell nearest (x, y), if any.
std::optional<semnav::common::v1::Pose2D> FreeCellNear(const GridMap& grid, double x, double y) {
  const std::string* layer = nullptr;
  for (const auto& l : grid.layers()) {
    if (l.kind() == semnav::common::v1::GRID_LAYER_KIND_HIERARCHICAL) layer = &l.data();
  }
  if (layer == nullptr) return std::nullopt;
  std::optional<semnav::common::v1::Pose2D> best;
  double best_d = 0.0;
  for (uint32_t r = 0; r < grid.height(); ++r) {
    for (uint32_t c = 0; c < grid.width(); ++c) {
      if ((*layer)[r * grid.width() + c] != 0) continue;
      semnav::common::v1::Pose2D pose;
      pose.set_x(grid.origin().x() + (c + 0.5) * grid.resolution());
      pose.set_y(grid.origin().y() + (r + 0.5) * grid.resolution());
      const double d = std::hypot(pose.x() - x, pose.y() - y);
      if (!best || d < best_d) {
        best = pose;
        best_d = d;
      }
    }
  }
  return best;
}

// Streams `frames` frames of the standard synthetic room's tour to mapping, from `*stamp` on.
void StreamRoomTour(mpb::MappingService::Stub& mapping, int frames, int64_t* stamp) {
  grpc::ClientContext context;
  auto stream = mapping.StreamFrames(&context);
  const mapping::testing::SyntheticRoom room = mapping::testing::StandardRoom();
  for (const mapping::CameraPose& pose : mapping::testing::RoomTour(room, frames)) {
    mpb::StreamFramesRequest request;
    *request.mutable_frame() =
        mapping::testing::FrameToProto(mapping::testing::RenderFrame(room, pose, *stamp));
    request.mutable_frame()->mutable_header()->set_robot_id("robot-1");
    *stamp += 100'000'000;
    ASSERT_TRUE(stream->Write(request));
    mpb::StreamFramesResponse response;
    ASSERT_TRUE(stream->Read(&response));
  }
  stream->WritesDone();
  ASSERT_TRUE(stream->Finish().ok());
}

// Mapping and, against it, planning, each from a config in a fresh folder named `name`.
struct TwoServices {
  std::unique_ptr<testing::ServiceProcess> mapping;
  std::unique_ptr<testing::ServiceProcess> planning;
};
TwoServices StartBoth(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/mapping.yaml") << "mapping:\n  store_directory: " << dir << "/store\n";
  absl::StatusOr<std::unique_ptr<testing::ServiceProcess>> mapping =
      testing::ServiceProcess::Start("semnav-mapping", {"--config", dir + "/mapping.yaml"});
  EXPECT_TRUE(mapping.ok()) << mapping.status();
  if (!mapping.ok()) return {};
  std::ofstream(dir + "/planning.yaml")
      << "planning:\n  mapping:\n    address: " << (*mapping)->address() << "\n";
  absl::StatusOr<std::unique_ptr<testing::ServiceProcess>> planning =
      testing::ServiceProcess::Start("semnav-planning", {"--config", dir + "/planning.yaml"});
  EXPECT_TRUE(planning.ok()) << planning.status();
  if (!planning.ok()) return {};
  return {*std::move(mapping), *std::move(planning)};
}

// The standard synthetic room mapped from a short tour by a real mapping service, a real planning
// service on it, and two free cells across the room, past the table-height box at x 3.0-3.6,
// y 1.0-1.6.
class PlanningWithMapping : public ::testing::Test {
 protected:
  void MapTheRoom(const std::string& name) {
    services_ = StartBoth(name);
    ASSERT_TRUE(services_.mapping && services_.planning);
    mapping_ = mpb::MappingService::NewStub(services_.mapping->channel());
    StreamRoomTour(*mapping_, 6, &stamp_);
    grpc::ClientContext context;
    ASSERT_TRUE(mapping_->GetGridMap(&context, {}, &grid_).ok());
    ASSERT_GT(grid_.grid().revision(), 0u);
    start_ = FreeCellNear(grid_.grid(), 1.5, 1.3);
    goal_ = FreeCellNear(grid_.grid(), 4.3, 1.3);
    ASSERT_TRUE(start_ && goal_);
    planning_ = pb::PlanningService::NewStub(services_.planning->channel());
  }

  // The map revision of the grid a live-map PlanPath from start_ to goal_ was planned on.
  uint64_t PlanRevision(uint32_t max_age_ms) {
    pb::PlanPathRequest request;
    request.mutable_source()->mutable_live_map()->set_max_age_ms(max_age_ms);
    *request.mutable_start() = *start_;
    *request.mutable_goal() = *goal_;
    pb::PlanPathResponse response;
    grpc::ClientContext context;
    const grpc::Status status = planning_->PlanPath(&context, request, &response);
    EXPECT_TRUE(status.ok()) << status.error_message();
    return response.map_revision();
  }

  TwoServices services_;
  std::unique_ptr<mpb::MappingService::Stub> mapping_;
  std::unique_ptr<pb::PlanningService::Stub> planning_;
  int64_t stamp_ = 1'000'000'000;
  mpb::GetGridMapResponse grid_;
  std::optional<semnav::common::v1::Pose2D> start_;
  std::optional<semnav::common::v1::Pose2D> goal_;
};

TEST_F(PlanningWithMapping, LiveMapPlanEqualsInlinePlanOnTheSameGrid) {
  MapTheRoom("planning_mapping_contract");
  if (HasFatalFailure()) return;
  pb::PlanPathRequest live;
  live.mutable_source()->mutable_live_map();
  *live.mutable_start() = *start_;
  *live.mutable_goal() = *goal_;
  pb::PlanPathRequest inline_grid = live;
  *inline_grid.mutable_source()->mutable_grid() = grid_.grid();

  pb::PlanPathResponse from_live;
  pb::PlanPathResponse from_inline;
  grpc::ClientContext c1;
  const grpc::Status live_status = planning_->PlanPath(&c1, live, &from_live);
  ASSERT_TRUE(live_status.ok()) << live_status.error_message();
  grpc::ClientContext c2;
  ASSERT_TRUE(planning_->PlanPath(&c2, inline_grid, &from_inline).ok());
  EXPECT_EQ(from_live.map_revision(), grid_.grid().revision());
  EXPECT_DOUBLE_EQ(from_live.length_m(), from_inline.length_m());
  EXPECT_EQ(from_live.path_size(), from_inline.path_size());
  // The table box lies on the straight line, so the path detours round it.
  const double straight = std::hypot(goal_->x() - start_->x(), goal_->y() - start_->y());
  EXPECT_GT(from_live.length_m(), straight + 0.1) << "straight " << straight;
}

// LiveMapGrid.max_age_ms: a call that accepts an age is answered from the grid an earlier call
// fetched, though mapping has moved on; a call that accepts none gets mapping's grid of now.
TEST_F(PlanningWithMapping, AGridOfAnAcceptedAgeIsTheOneFetchedBefore) {
  MapTheRoom("planning_mapping_kept_grid");
  if (HasFatalFailure()) return;
  const uint64_t first = grid_.grid().revision();
  EXPECT_EQ(PlanRevision(0), first);  // fetched now, and kept
  StreamRoomTour(*mapping_, 2, &stamp_);
  EXPECT_EQ(PlanRevision(10000), first);  // the kept grid is young enough
  const uint64_t now = PlanRevision(0);   // fetched again
  EXPECT_GT(now, first);
  EXPECT_EQ(PlanRevision(10000), now);  // and the newer one is kept
}

// planning.live_map_refresh_ahead (0.5): a call that finds the kept grid older than half its
// max_age_ms is answered from it and has it fetched again meanwhile, so a later call within the
// same age gets mapping's newer grid without fetching it itself.
TEST_F(PlanningWithMapping, AKeptGridPastHalfItsAgeIsFetchedAgainAhead) {
  MapTheRoom("planning_mapping_refresh_ahead");
  if (HasFatalFailure()) return;
  constexpr uint32_t kMaxAgeMs = 4000;
  const absl::Time fetched_by = absl::Now();
  const uint64_t first = PlanRevision(0);  // fetched now, and kept
  StreamRoomTour(*mapping_, 2, &stamp_);
  // Within half the age: the kept grid, and no refresh.
  if (absl::Now() - fetched_by < absl::Milliseconds(kMaxAgeMs / 2)) {
    EXPECT_EQ(PlanRevision(kMaxAgeMs), first);
  }
  absl::SleepFor(fetched_by + absl::Milliseconds(kMaxAgeMs / 2 + 200) - absl::Now());
  EXPECT_EQ(PlanRevision(kMaxAgeMs), first);  // still young enough: answered from it at once
  uint64_t later = first;
  while (later == first && absl::Now() - fetched_by < absl::Milliseconds(kMaxAgeMs - 300)) {
    absl::SleepFor(absl::Milliseconds(100));
    later = PlanRevision(kMaxAgeMs);
  }
  EXPECT_GT(later, first) << "the kept grid was not fetched again ahead of its age";
}

}  // namespace
}  // namespace semnav::planning
