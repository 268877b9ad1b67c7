// Why a search episode failed, from its trace (episode_trace.h): one cause per failed episode,
// so the mission report can count causes per strategy and group and each fix shows up as a
// cause that shrinks (issue 14, item 2).
#pragma once

#include <string_view>

#include "clients/sim/loop/episode_trace.h"

namespace semnav::sim::loop {

enum class FailureCause {
  kNone,                  // the episode succeeded
  kRefusedInstruction,    // the gateway refused the instruction
  kWrongObjectVerified,   // the task declared success farther than stopped_short_m from any target
  kStoppedOutsideRegion,  // declared success near a target but outside its success region
                          // (short of it, or on the wrong side of a wall)
  kReachedNeverStopped,   // was in the success region with the target seen, never declared
  kGoalOutsideMap,        // the robot was sent off the world, or its planner said so
  kCollisionLoop,         // blocked again and again (collisions, grazing)
  kNoPath,                // planning found no path again and again
  kStuckInState,          // no progress for stuck_s: the robot stayed within stuck_radius_m
  kSeenNeverApproached,   // the target was detected but the robot never reached its region
  kGaveUpSearching,       // the task failed having not found the target
  kTaskFailed,            // the task failed for another reason
  kBudgetSpentExploring,  // the budget ran out before the target was ever seen
};

// snake_case name for reports: "budget_spent_exploring", ...; "" for kNone.
std::string_view FailureCauseName(FailureCause cause);

// Thresholds of the taxonomy; defaults suit seed 004's 500 steps of 0.5 s.
struct FailureTaxonomyConfig {
  double stuck_s = 60.0;          // no progress for this long is being stuck
  double stuck_radius_m = 1.0;    // progress is leaving a disc of this radius
  int collision_loop_blocks = 4;  // BLOCKED answers that make a collision loop
  int no_path_events = 3;         // "no path" answers and task reasons that make it the cause
  int outside_map_events = 2;     // goals off the world or "outside" answers that make it the cause
  double stopped_short_m = 2.0;   // a declared stop this near a target is "stopped outside region"
};

// The first cause that applies, checked in the order of the enum after kNone: the most
// specific evidence first, "budget spent exploring" last. kNone when trace.success.
FailureCause ClassifyFailure(const EpisodeTrace& trace, const FailureTaxonomyConfig& config = {});

}  // namespace semnav::sim::loop
