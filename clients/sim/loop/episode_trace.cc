#include "clients/sim/loop/episode_trace.h"

namespace semnav::sim::loop {

void RecordTaskChange(EpisodeTrace& trace, double time_s,
                      const semnav::reasoning::v1::TaskSnapshot& task) {
  if (!trace.task.empty()) {
    const TaskChange& last = trace.task.back();
    if (last.status == task.status() && last.phase == task.phase() && last.reason == task.reason())
      return;
  }
  trace.task.push_back(TaskChange{time_s, task.status(), task.phase(), task.reason()});
}

void RecordFeedback(EpisodeTrace& trace, double time_s, semnav::reasoning::v1::FeedbackKind kind,
                    const std::string& detail) {
  trace.feedback.push_back(FeedbackEvent{time_s, kind, detail});
}

void RecordNavigateGoal(EpisodeTrace& trace, double time_s, const Eigen::Vector2d& goal) {
  trace.goals.push_back(NavigateGoal{time_s, goal});
}

void RecordDetection(EpisodeTrace& trace, double time_s, const World& world,
                     const std::string& label, int object_index) {
  if (trace.target_first_seen_s.has_value() || object_index < 0 ||
      object_index >= static_cast<int>(world.objects.size())) {
    return;
  }
  if (world.objects[static_cast<size_t>(object_index)].label == label)
    trace.target_first_seen_s = time_s;
}

void RecordSample(EpisodeTrace& trace, double time_s, const Eigen::Vector2d& position,
                  const World& world, const std::string& label, const SuccessRegion& region) {
  trace.samples.push_back(TraceSample{time_s, position,
                                      DistanceToNearestInstance(world, label, position),
                                      region.Contains(position)});
}

}  // namespace semnav::sim::loop
