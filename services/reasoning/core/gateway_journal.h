// What the gateway keeps across its own death: tasks (their instruction, subgoals and progress),
// leases, the task counter and the event log. A crash loses at most the last flush interval.
//   <directory>/gateway_state.snj   tasks, leases and counters: one checksummed frame
//                                   (storage::FrameWithChecksum), replaced atomically
//   <directory>/events.log          one line per event, "<crc32 hex> <json>\n", appended and
//                                   fdatasync'ed per flush; a torn or damaged line is skipped
// Plain values, no transport: the hub converts.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "absl/time/time.h"
#include "services/reasoning/core/event_log.h"
#include "services/reasoning/core/exploration_context.h"
#include "services/reasoning/core/exploration_strategy.h"
#include "services/reasoning/core/lease_table.h"
#include "services/reasoning/core/subgoal.h"
#include "services/reasoning/core/task_executor.h"

namespace semnav::reasoning {

struct JournaledTask {
  std::string task_id;
  std::string robot_id;
  std::string instruction;
  std::string source;                           // decomposition source ("rules", "model", ...)
  std::optional<ExplorationStrategy> strategy;  // nullopt = the configured default
  std::optional<SearchArea> search_area;
  std::vector<Subgoal> subgoals;
  // state, subgoal_index, phase, reason, replans, explore_goals, model_requests (not the path
  // or target, which are found again from the live map).
  TaskProgress progress;
  int model_calls = 0;
  absl::Time created;
  absl::Time updated;
};

struct GatewayState {
  uint64_t next_task = 1;
  std::vector<JournaledTask> tasks;
  std::vector<LeaseInfo> leases;
};

// JSON text of the state and back; DATA_LOSS naming the first bad field.
std::string EncodeGatewayState(const GatewayState& state);
absl::StatusOr<GatewayState> DecodeGatewayState(absl::string_view json);

// One events.log line (with its newline) and back; nullopt for a damaged or torn line.
std::string EncodeEventLine(const LoggedEvent& event);
std::optional<LoggedEvent> DecodeEventLine(absl::string_view line);

class GatewayJournal {
 public:
  struct Recovered {
    GatewayState state;
    std::vector<LoggedEvent> events;  // the newest `retained_events`, oldest first
    int damaged_event_lines = 0;
  };

  // Creates the directory if needed.
  static absl::StatusOr<GatewayJournal> Open(std::string directory, std::size_t retained_events);

  // The last flushed state (empty when there is none); DATA_LOSS when the state file is damaged.
  // Compacts events.log to the retained events.
  absl::StatusOr<Recovered> Recover();
  absl::Status SaveState(const GatewayState& state);
  // Appends with one write and one fdatasync; compacts when the log holds twice the retained
  // events.
  absl::Status AppendEvents(const std::vector<LoggedEvent>& events);

  std::string state_path() const;
  std::string events_path() const;

 private:
  GatewayJournal(std::string directory, std::size_t retained_events)
      : directory_(std::move(directory)), retained_events_(retained_events) {}
  // Rewrites events.log with only `events` (atomically).
  absl::Status Rewrite(const std::vector<LoggedEvent>& events);
  // The log's intact events, newest `retained_events_`, oldest first.
  std::vector<LoggedEvent> ReadEvents(int* damaged) const;

  std::string directory_;
  std::size_t retained_events_;
  std::size_t lines_in_log_ = 0;
};

}  // namespace semnav::reasoning
