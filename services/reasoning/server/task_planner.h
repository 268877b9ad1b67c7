// The PathPlanner each task's executor gets: paths come from the shared planner unchanged;
// exploration goals are asked with the task's strategy and its semantic context (target, scene
// graph, visited places, commonsense co-occurrence), which the executor itself does not know.
#pragma once

#include <functional>
#include <string>

#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/navigation_interfaces.h"

namespace semnav::reasoning {

// Planning's SelectExplorationGoal with a strategy and context (PlanningClient).
class ExplorationService {
 public:
  virtual ~ExplorationService() = default;
  // `strategy`: NEAREST_FRONTIER, COVERAGE_MAX, SEMANTIC_FRONTIER or EROI_UTILITY; "" = the
  // configured default. NOT_FOUND when planning has no goal.
  virtual absl::StatusOr<Eigen::Vector3d> SelectGoal(const ExplorationQuery& query, const std::string& strategy,
                                                     const ExplorationContext& context) = 0;
};

class TaskPlanner final : public PathPlanner {
 public:
  // `explorer` may be null (no planning service: the shared planner's exploration fallback).
  // `context` is called for every exploration goal, on the caller's thread.
  TaskPlanner(PathPlanner* paths, ExplorationService* explorer, std::string strategy,
              std::function<ExplorationContext()> context)
      : paths_(paths), explorer_(explorer), strategy_(std::move(strategy)), context_(std::move(context)) {}

  absl::StatusOr<std::vector<Eigen::Vector3d>> Plan(const PathQuery& query) override { return paths_->Plan(query); }
  absl::StatusOr<Eigen::Vector3d> ExplorationGoal(const ExplorationQuery& query) override {
    if (explorer_ == nullptr) return paths_->ExplorationGoal(query);
    return explorer_->SelectGoal(query, strategy_, context_());
  }
  const std::string& strategy() const { return strategy_; }

 private:
  PathPlanner* paths_;
  ExplorationService* explorer_;
  std::string strategy_;
  std::function<ExplorationContext()> context_;
};

}  // namespace semnav::reasoning
