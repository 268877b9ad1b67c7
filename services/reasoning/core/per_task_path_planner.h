// The PathPlanner each task's executor gets: paths come from the shared planner; exploration goals
// are asked with the task's strategy and its semantic context (target, scene graph, visited
// places, commonsense co-occurrence), which the executor itself does not know; a place where the
// vision model saw the target comes first (NextSighting, looked at from where planning says). Both
// carry the live-map age the robot's session accepts.
// Every call to planning goes through the task's RemoteCallRunner, which lets the gateway run it
// without its lock (docs/algorithms/gateway.md, "Remote calls").
#pragma once

#include <algorithm>
#include <functional>
#include <optional>

#include "absl/functional/function_ref.h"
#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/exploration_strategy.h"
#include "services/reasoning/core/navigation_interfaces.h"
#include "services/reasoning/core/sighting_goal.h"

namespace semnav::reasoning {

// Planning's SelectExplorationGoal with a strategy and context (PlanningClient).
class ExplorationService {
 public:
  virtual ~ExplorationService() = default;
  // `strategy`: nullopt = the configured default. NOT_FOUND when planning has no goal.
  virtual absl::StatusOr<Eigen::Vector3d> SelectGoal(const ExplorationQuery& query,
                                                     std::optional<ExplorationStrategy> strategy,
                                                     const ExplorationContext& context) = 0;
};

// Runs one remote call (`call`) on the caller's thread; the gateway's runner releases its lock
// around it and holds the task's other events back meanwhile. Null = run it as it is.
using RemoteCallRunner = std::function<void(absl::FunctionRef<void()> call)>;

class PerTaskPathPlanner final : public PathPlanner {
 public:
  // `explorer` may be null (no planning service: the shared planner's exploration fallback).
  // `context` is called for every exploration goal, on the caller's thread, before the call.
  // `strategy`: nullopt = the configured default. `live_map_max_age_ms` (called before every
  // call, on the caller's thread) sets the queries' live_map_max_age_ms; null = leave it.
  PerTaskPathPlanner(PathPlanner* paths, ExplorationService* explorer,
                     std::optional<ExplorationStrategy> strategy,
                     std::function<ExplorationContext()> context, RemoteCallRunner remote = nullptr,
                     std::function<int()> live_map_max_age_ms = nullptr)
      : paths_(paths),
        explorer_(explorer),
        strategy_(strategy),
        context_(std::move(context)),
        remote_(std::move(remote)),
        live_map_max_age_ms_(std::move(live_map_max_age_ms)) {}

  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override {
    PathQuery asked = query;
    if (live_map_max_age_ms_) asked.live_map_max_age_ms = live_map_max_age_ms_();
    absl::StatusOr<std::vector<Eigen::Vector3d>> path;
    Remote([&] { path = paths_->Plan(asked); });
    return path;
  }
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) override {
    ExplorationQuery asked = query;
    if (live_map_max_age_ms_) asked.live_map_max_age_ms = live_map_max_age_ms_();
    absl::StatusOr<Eigen::Vector3d> goal;
    if (explorer_ == nullptr) {
      Remote([&] { goal = paths_->ExplorationGoal(asked); });
      return goal;
    }
    const ExplorationContext context = context_();
    // A place the vision model saw the target at is looked at before planning's next goal.
    if (context.eroi_inspect_distance_m > 0.0) {
      if (std::optional<Eigen::Vector3d> sighting = NextSighting(
              context.eroi_sightings, asked, context.eroi_inspect_distance_m, looks_)) {
        return LookGoalFromPlanning(asked, context, *sighting);
      }
    }
    Remote([&] { goal = explorer_->SelectGoal(asked, strategy_, context); });
    return goal;
  }
  std::optional<ExplorationStrategy> strategy() const { return strategy_; }

 private:
  // Planning's goal to look at `sighting` from (it knows the walls); the straight line when
  // planning has no answer but is there.
  absl::StatusOr<Eigen::Vector3d> LookGoalFromPlanning(const ExplorationQuery& asked,
                                                       const ExplorationContext& context,
                                                       const Eigen::Vector3d& sighting) {
    ExplorationContext look = context;
    look.look_at = sighting;
    look.look_distance_m = context.eroi_inspect_distance_m;
    absl::StatusOr<Eigen::Vector3d> goal;
    Remote([&] { goal = explorer_->SelectGoal(asked, strategy_, look); });
    if (absl::IsUnavailable(goal.status())) return goal;
    if (!goal.ok()) goal = StraightLookGoal(sighting, asked, context.eroi_inspect_distance_m);
    // The same answer again adds nothing; the list stays bounded by what the task saw.
    const bool known = std::any_of(looks_.begin(), looks_.end(), [&](const SightingLook& l) {
      return l.sighting == sighting && (l.goal - *goal).head<2>().norm() < 0.05;
    });
    if (!known && looks_.size() < kMaxLooks) looks_.push_back({sighting, *goal});
    return goal;
  }
  void Remote(absl::FunctionRef<void()> call) {
    if (remote_) {
      remote_(call);
    } else {
      call();
    }
  }

  PathPlanner* paths_;
  ExplorationService* explorer_;
  std::optional<ExplorationStrategy> strategy_;
  std::function<ExplorationContext()> context_;
  RemoteCallRunner remote_;
  std::function<int()> live_map_max_age_ms_;
  static constexpr size_t kMaxLooks = 4096;
  std::vector<SightingLook> looks_;  // goals given to look at sightings
};

}  // namespace semnav::reasoning
