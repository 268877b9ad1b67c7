#pragma once

#include <gtest/gtest.h>

#include <memory>

#include "semnav/planning/v1/planning_service.grpc.pb.h"
#include "tests/support/service_process.h"

namespace semnav::planning {

// Fixture base: one real semnav-planning binary per test suite.
class PlanningBinaryTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    absl::StatusOr<std::unique_ptr<testing::ServiceProcess>> started =
        testing::ServiceProcess::Start("semnav-planning");
    ASSERT_TRUE(started.ok()) << started.status();
    process_ = std::move(*started);
  }
  static void TearDownTestSuite() { process_.reset(); }

  static std::unique_ptr<semnav::planning::v1::PlanningService::Stub> Stub() {
    return semnav::planning::v1::PlanningService::NewStub(process_->channel());
  }

 private:
  static inline std::unique_ptr<testing::ServiceProcess> process_;
};

}  // namespace semnav::planning
