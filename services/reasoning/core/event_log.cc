#include "services/reasoning/core/event_log.h"

#include <algorithm>
#include <iterator>

namespace semnav::reasoning {

const LoggedEvent& EventLog::Append(int kind, std::string robot_id, std::string task_id,
                                    std::string message, absl::Time now) {
  events_.push_back(
      {next_id_++, now, kind, std::move(robot_id), std::move(task_id), std::move(message)});
  if (events_.size() > retained_) events_.pop_front();
  return events_.back();
}

std::vector<LoggedEvent> EventLog::After(uint64_t last_id, const std::string& robot_id,
                                         const std::string& task_id, bool* truncated) const {
  *truncated = !events_.empty() && events_.front().id > last_id + 1;
  std::vector<LoggedEvent> out;
  for (const LoggedEvent& event : events_) {
    if (event.id > last_id && (robot_id.empty() || event.robot_id == robot_id) &&
        (task_id.empty() || event.task_id == task_id)) {
      out.push_back(event);
    }
  }
  return out;
}

void EventLog::Restore(std::vector<LoggedEvent> events) {
  events_.assign(std::make_move_iterator(events.begin()), std::make_move_iterator(events.end()));
  while (events_.size() > retained_) events_.pop_front();
  if (!events_.empty()) next_id_ = std::max(next_id_, events_.back().id + 1);
}

}  // namespace semnav::reasoning
