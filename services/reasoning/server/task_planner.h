// The PathPlanner each task's executor gets: paths come from the shared planner unchanged;
// exploration goals are asked with the task's strategy and its semantic context (target, scene
// graph, visited places, commonsense co-occurrence), which the executor itself does not know.
#pragma once

#include <functional>
#include <optional>

#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/exploration_strategy.h"
#include "services/reasoning/core/navigation_interfaces.h"

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

class TaskPlanner final : public PathPlanner {
 public:
  // `explorer` may be null (no planning service: the shared planner's exploration fallback).
  // `context` is called for every exploration goal, on the caller's thread.
  // `strategy`: nullopt = the configured default.
  TaskPlanner(PathPlanner* paths, ExplorationService* explorer, std::optional<ExplorationStrategy> strategy,
              std::function<ExplorationContext()> context)
      : paths_(paths), explorer_(explorer), strategy_(strategy), context_(std::move(context)) {}

  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override { return paths_->Plan(query); }
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) override {
    if (explorer_ == nullptr) return paths_->ExplorationGoal(query);
    return explorer_->SelectGoal(query, strategy_, context_());
  }
  std::optional<ExplorationStrategy> strategy() const { return strategy_; }

 private:
  PathPlanner* paths_;
  ExplorationService* explorer_;
  std::optional<ExplorationStrategy> strategy_;
  std::function<ExplorationContext()> context_;
};

}  // namespace semnav::reasoning
