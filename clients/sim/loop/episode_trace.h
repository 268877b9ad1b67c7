// What happened in one closed-loop episode, as values the failure taxonomy reads
// (failure_taxonomy.h): task changes, the robot's feedback, the goals it was sent, where it was
// after each step, and when it first saw the target.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "clients/sim/core/episode_metrics.h"
#include "clients/sim/core/world.h"
#include "semnav/reasoning/v1/robot_session.pb.h"
#include "semnav/reasoning/v1/task.pb.h"

namespace semnav::sim::loop {

// The task as the operator saw it after a change of status, phase or reason.
struct TaskChange {
  double time_s = 0.0;
  semnav::reasoning::v1::TaskStatus status = semnav::reasoning::v1::TASK_STATUS_UNSPECIFIED;
  std::string phase;
  std::string reason;
};

// The robot's answer to a command: accepted when started, then reached, failed or blocked.
struct FeedbackEvent {
  double time_s = 0.0;
  semnav::reasoning::v1::FeedbackKind kind = semnav::reasoning::v1::FEEDBACK_KIND_UNSPECIFIED;
  std::string detail;
};

struct NavigateGoal {
  double time_s = 0.0;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
};

// The robot after one step.
struct TraceSample {
  double time_s = 0.0;
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double target_distance_m = 0.0;  // horizontal, to the nearest target footprint
  bool in_success_region = false;  // SuccessRegion::Contains
};

struct EpisodeTrace {
  std::vector<TaskChange> task;
  std::vector<FeedbackEvent> feedback;
  std::vector<NavigateGoal> goals;
  std::vector<TraceSample> samples;
  bool instruction_refused = false;           // the gateway said no to the instruction
  std::optional<double> target_first_seen_s;  // first detection of an instance of the target label
  bool budget_spent = false;                  // the step budget ran out with the task running
  bool stop_declared = false;                 // STOP at the end of a SUCCEEDED task
  bool success = false;                       // the episode's score
  double end_s = 0.0;
  Eigen::Vector2d bounds_min = Eigen::Vector2d::Zero();  // the world's, for goals off the map
  Eigen::Vector2d bounds_max = Eigen::Vector2d::Zero();
};

// Recording, one call per event; each is cheap and leaves the episode's behaviour alone.
// Appends `task`'s status, phase and reason when any differs from the last change.
void RecordTaskChange(EpisodeTrace& trace, double time_s,
                      const semnav::reasoning::v1::TaskSnapshot& task);
void RecordFeedback(EpisodeTrace& trace, double time_s, semnav::reasoning::v1::FeedbackKind kind,
                    const std::string& detail);
void RecordNavigateGoal(EpisodeTrace& trace, double time_s, const Eigen::Vector2d& goal);
// Notes the first detection of an object labelled `label` (`object_index` into world.objects).
void RecordDetection(EpisodeTrace& trace, double time_s, const World& world,
                     const std::string& label, int object_index);
void RecordSample(EpisodeTrace& trace, double time_s, const Eigen::Vector2d& position,
                  const World& world, const std::string& label, const SuccessRegion& region);

}  // namespace semnav::sim::loop
