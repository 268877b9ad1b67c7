#include "services/reasoning/core/gateway_journal.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_split.h"
#include "services/common/storage/durable_file.h"

namespace semnav::reasoning {
namespace {

using nlohmann::json;

constexpr char kStateMagic[] = "SNGWJ1\n";
constexpr char kStateFile[] = "gateway_state.snj";
constexpr char kEventsFile[] = "events.log";

int64_t ToNanos(absl::Time t) { return absl::ToUnixNanos(t); }
absl::Time FromNanos(int64_t ns) { return absl::FromUnixNanos(ns); }

std::optional<TaskState> ParseState(const std::string& name) {
  for (TaskState s : {TaskState::kRunning, TaskState::kPaused, TaskState::kSucceeded,
                      TaskState::kFailed, TaskState::kCancelled}) {
    if (TaskStateName(s) == name) return s;
  }
  return std::nullopt;
}

json TargetJson(const TargetSpec& t) {
  return {{"name", t.name},         {"is_room", t.is_room}, {"colours", t.colours},
          {"relation", t.relation}, {"anchor", t.anchor},   {"text", t.text}};
}

json SubgoalJson(const Subgoal& g) {
  return {{"type", std::string(SubgoalTypeName(g.type))},
          {"target", TargetJson(g.target)},
          {"distance_m", g.distance_m},
          {"duration_s", g.duration_s},
          {"reason", g.reason}};
}

json TaskJson(const JournaledTask& t) {
  json subgoals = json::array();
  for (const Subgoal& g : t.subgoals) subgoals.push_back(SubgoalJson(g));
  json out = {
      {"task_id", t.task_id},
      {"robot_id", t.robot_id},
      {"instruction", t.instruction},
      {"source", t.source},
      {"strategy", t.strategy.has_value() ? std::string(ExplorationStrategyName(*t.strategy)) : ""},
      {"subgoals", subgoals},
      {"state", std::string(TaskStateName(t.progress.state))},
      {"subgoal_index", t.progress.subgoal_index},
      {"phase", t.progress.phase},
      {"reason", t.progress.reason},
      {"replans", t.progress.replans},
      {"explore_goals", t.progress.explore_goals},
      {"model_requests", t.progress.model_requests},
      {"model_calls", t.model_calls},
      {"created_ns", ToNanos(t.created)},
      {"updated_ns", ToNanos(t.updated)}};
  if (t.search_area.has_value()) {
    out["search_area"] = {t.search_area->min.x(), t.search_area->min.y(), t.search_area->max.x(),
                          t.search_area->max.y()};
  }
  return out;
}

// Reads fields of one JSON object, remembering the first that is missing or of the wrong type.
class Fields {
 public:
  Fields(const json& object, std::string path) : object_(object), path_(std::move(path)) {}

  template <typename T>
  T Get(const char* name) {
    const auto it = object_.find(name);
    if (it == object_.end()) return Fail<T>(name, "is missing");
    try {
      return it->template get<T>();
    } catch (const json::exception&) {
      return Fail<T>(name, "has the wrong type");
    }
  }
  bool Has(const char* name) const { return object_.contains(name); }
  const std::string& path() const { return path_; }
  absl::Status status() const { return status_; }

 private:
  template <typename T>
  T Fail(const char* name, const char* why) {
    if (status_.ok())
      status_ = absl::DataLossError(absl::StrCat("gateway journal: ", path_, ".", name, " ", why));
    return T{};
  }
  const json& object_;
  std::string path_;
  absl::Status status_;
};

absl::StatusOr<Subgoal> SubgoalFrom(const json& j, const std::string& path) {
  if (!j.is_object())
    return absl::DataLossError(absl::StrCat("gateway journal: ", path, " is not an object"));
  Fields f(j, path);
  Subgoal g;
  const std::optional<SubgoalType> type = ParseSubgoalType(f.Get<std::string>("type"));
  const json target = f.Get<json>("target");
  g.distance_m = f.Get<double>("distance_m");
  g.duration_s = f.Get<double>("duration_s");
  g.reason = f.Get<std::string>("reason");
  if (!f.status().ok()) return f.status();
  if (!type.has_value())
    return absl::DataLossError(absl::StrCat("gateway journal: ", path, ".type is unknown"));
  g.type = *type;
  if (!target.is_object())
    return absl::DataLossError(absl::StrCat("gateway journal: ", path, ".target is not an object"));
  Fields t(target, path + ".target");
  g.target.name = t.Get<std::string>("name");
  g.target.is_room = t.Get<bool>("is_room");
  g.target.colours = t.Get<std::vector<std::string>>("colours");
  g.target.relation = t.Get<std::string>("relation");
  g.target.anchor = t.Get<std::string>("anchor");
  g.target.text = t.Get<std::string>("text");
  if (!t.status().ok()) return t.status();
  return g;
}

absl::StatusOr<JournaledTask> TaskFrom(const json& j, const std::string& path) {
  if (!j.is_object())
    return absl::DataLossError(absl::StrCat("gateway journal: ", path, " is not an object"));
  Fields f(j, path);
  JournaledTask t;
  t.task_id = f.Get<std::string>("task_id");
  t.robot_id = f.Get<std::string>("robot_id");
  t.instruction = f.Get<std::string>("instruction");
  t.source = f.Get<std::string>("source");
  const std::string strategy = f.Get<std::string>("strategy");  // "" = the configured default
  const json subgoals = f.Get<json>("subgoals");
  const std::optional<TaskState> state = ParseState(f.Get<std::string>("state"));
  t.progress.subgoal_index = f.Get<int>("subgoal_index");
  t.progress.phase = f.Get<std::string>("phase");
  t.progress.reason = f.Get<std::string>("reason");
  t.progress.replans = f.Get<int>("replans");
  t.progress.explore_goals = f.Get<int>("explore_goals");
  t.progress.model_requests = f.Get<int>("model_requests");
  t.model_calls = f.Get<int>("model_calls");
  t.created = FromNanos(f.Get<int64_t>("created_ns"));
  t.updated = FromNanos(f.Get<int64_t>("updated_ns"));
  if (f.Has("search_area")) {
    const auto area = f.Get<std::vector<double>>("search_area");
    if (area.size() != 4)
      return absl::DataLossError(
          absl::StrCat("gateway journal: ", path, ".search_area needs 4 numbers"));
    t.search_area = SearchArea{{area[0], area[1]}, {area[2], area[3]}};
  }
  if (!f.status().ok()) return f.status();
  if (!state.has_value())
    return absl::DataLossError(absl::StrCat("gateway journal: ", path, ".state is unknown"));
  t.progress.state = *state;
  if (!strategy.empty()) {
    t.strategy = ParseExplorationStrategy(strategy);
    if (!t.strategy.has_value()) {
      return absl::DataLossError(absl::StrCat("gateway journal: ", path, ".strategy is unknown"));
    }
  }
  if (t.task_id.empty() || t.robot_id.empty()) {
    return absl::DataLossError(absl::StrCat("gateway journal: ", path, " has no task or robot id"));
  }
  if (!subgoals.is_array() || subgoals.empty()) {
    return absl::DataLossError(
        absl::StrCat("gateway journal: ", path, ".subgoals must be a non-empty list"));
  }
  for (std::size_t i = 0; i < subgoals.size(); ++i) {
    absl::StatusOr<Subgoal> g = SubgoalFrom(subgoals[i], absl::StrCat(path, ".subgoals[", i, "]"));
    if (!g.ok()) return g.status();
    t.subgoals.push_back(*std::move(g));
  }
  if (t.progress.subgoal_index < 0 ||
      t.progress.subgoal_index >= static_cast<int>(t.subgoals.size())) {
    return absl::DataLossError(
        absl::StrCat("gateway journal: ", path, ".subgoal_index is out of range"));
  }
  return t;
}

absl::Status ErrnoStatus(absl::string_view what, const std::string& path) {
  return absl::InternalError(absl::StrCat(what, " ", path, ": ", std::strerror(errno)));
}

}  // namespace

std::string EncodeGatewayState(const GatewayState& state) {
  json tasks = json::array();
  for (const JournaledTask& t : state.tasks) tasks.push_back(TaskJson(t));
  json leases = json::array();
  for (const LeaseInfo& l : state.leases) {
    leases.push_back({{"lease_id", l.lease_id},
                      {"robot_id", l.robot_id},
                      {"holder", l.holder},
                      {"expires_ns", ToNanos(l.expires_at)}});
  }
  return json{{"version", 1}, {"next_task", state.next_task}, {"tasks", tasks}, {"leases", leases}}
      .dump();
}

absl::StatusOr<GatewayState> DecodeGatewayState(absl::string_view text) {
  const json root = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (!root.is_object())
    return absl::DataLossError("gateway journal: the state is not a JSON object");
  Fields f(root, "state");
  GatewayState state;
  const int version = f.Get<int>("version");
  state.next_task = f.Get<uint64_t>("next_task");
  const json tasks = f.Get<json>("tasks");
  const json leases = f.Get<json>("leases");
  if (!f.status().ok()) return f.status();
  if (version != 1)
    return absl::DataLossError(absl::StrCat("gateway journal: unknown version ", version));
  if (!tasks.is_array() || !leases.is_array())
    return absl::DataLossError("gateway journal: tasks and leases must be lists");
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    absl::StatusOr<JournaledTask> t = TaskFrom(tasks[i], absl::StrCat("tasks[", i, "]"));
    if (!t.ok()) return t.status();
    state.tasks.push_back(*std::move(t));
  }
  for (std::size_t i = 0; i < leases.size(); ++i) {
    if (!leases[i].is_object())
      return absl::DataLossError(absl::StrCat("gateway journal: leases[", i, "] is not an object"));
    Fields l(leases[i], absl::StrCat("leases[", i, "]"));
    LeaseInfo lease;
    lease.lease_id = l.Get<std::string>("lease_id");
    lease.robot_id = l.Get<std::string>("robot_id");
    lease.holder = l.Get<std::string>("holder");
    lease.expires_at = FromNanos(l.Get<int64_t>("expires_ns"));
    if (!l.status().ok()) return l.status();
    state.leases.push_back(std::move(lease));
  }
  return state;
}

std::string EncodeEventLine(const LoggedEvent& event) {
  const std::string body = json{{"id", event.id},           {"time_ns", ToNanos(event.time)},
                                {"kind", event.kind},       {"robot_id", event.robot_id},
                                {"task_id", event.task_id}, {"message", event.message}}
                               .dump();
  return absl::StrFormat("%08x %s\n", storage::Crc32(body), body);
}

std::optional<LoggedEvent> DecodeEventLine(absl::string_view line) {
  if (!line.empty() && line.back() == '\n') line.remove_suffix(1);
  if (line.size() < 10 || line[8] != ' ') return std::nullopt;
  uint32_t crc = 0;
  if (!absl::SimpleHexAtoi(line.substr(0, 8), &crc)) return std::nullopt;
  const absl::string_view body = line.substr(9);
  if (storage::Crc32(body) != crc) return std::nullopt;
  const json j = json::parse(body.begin(), body.end(), nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return std::nullopt;
  Fields f(j, "event");
  LoggedEvent event;
  event.id = f.Get<uint64_t>("id");
  event.time = FromNanos(f.Get<int64_t>("time_ns"));
  event.kind = f.Get<int>("kind");
  event.robot_id = f.Get<std::string>("robot_id");
  event.task_id = f.Get<std::string>("task_id");
  event.message = f.Get<std::string>("message");
  if (!f.status().ok()) return std::nullopt;
  return event;
}

absl::StatusOr<GatewayJournal> GatewayJournal::Open(std::string directory,
                                                    std::size_t retained_events) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error)
    return absl::InternalError(absl::StrCat("cannot create ", directory, ": ", error.message()));
  return GatewayJournal(std::move(directory), std::max<std::size_t>(1, retained_events));
}

std::string GatewayJournal::state_path() const {
  return (std::filesystem::path(directory_) / kStateFile).string();
}
std::string GatewayJournal::events_path() const {
  return (std::filesystem::path(directory_) / kEventsFile).string();
}

std::vector<LoggedEvent> GatewayJournal::ReadEvents(int* damaged) const {
  std::deque<LoggedEvent> events;
  absl::StatusOr<std::string> text = storage::ReadWholeFile(events_path());
  if (!text.ok()) return {};
  for (absl::string_view line : absl::StrSplit(*text, '\n', absl::SkipEmpty())) {
    std::optional<LoggedEvent> event = DecodeEventLine(line);
    if (!event.has_value()) {
      ++*damaged;
      continue;
    }
    // Ids only grow; a line out of order is a leftover of a damaged write.
    if (!events.empty() && event->id <= events.back().id) {
      ++*damaged;
      continue;
    }
    events.push_back(*std::move(event));
    if (events.size() > retained_events_) events.pop_front();
  }
  return {events.begin(), events.end()};
}

absl::StatusOr<GatewayJournal::Recovered> GatewayJournal::Recover() {
  Recovered out;
  absl::StatusOr<std::string> file = storage::ReadWholeFile(state_path());
  if (file.ok()) {
    absl::StatusOr<std::string> payload = storage::PayloadOfFrame(kStateMagic, *file, state_path());
    if (!payload.ok()) return payload.status();
    absl::StatusOr<GatewayState> state = DecodeGatewayState(*payload);
    if (!state.ok()) return state.status();
    out.state = *std::move(state);
  } else if (!absl::IsNotFound(file.status())) {
    return file.status();
  }
  out.events = ReadEvents(&out.damaged_event_lines);
  if (absl::Status s = Rewrite(out.events); !s.ok()) return s;
  return out;
}

absl::Status GatewayJournal::SaveState(const GatewayState& state) {
  return storage::WriteFileAtomically(
      state_path(), storage::FrameWithChecksum(kStateMagic, EncodeGatewayState(state)));
}

absl::Status GatewayJournal::Rewrite(const std::vector<LoggedEvent>& events) {
  std::string text;
  for (const LoggedEvent& event : events) text += EncodeEventLine(event);
  if (absl::Status s = storage::WriteFileAtomically(events_path(), text); !s.ok()) return s;
  lines_in_log_ = events.size();
  return absl::OkStatus();
}

absl::Status GatewayJournal::AppendEvents(const std::vector<LoggedEvent>& events) {
  if (events.empty()) return absl::OkStatus();
  std::string text;
  for (const LoggedEvent& event : events) text += EncodeEventLine(event);
  const std::string path = events_path();
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) return ErrnoStatus("open", path);
  std::size_t written = 0;
  absl::Status status;
  while (written < text.size() && status.ok()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0)
      status = ErrnoStatus("write", path);
    else
      written += static_cast<std::size_t>(n);
  }
  if (status.ok() && ::fdatasync(fd) != 0) status = ErrnoStatus("fdatasync", path);
  ::close(fd);
  if (!status.ok()) return status;
  lines_in_log_ += events.size();
  if (lines_in_log_ <= 2 * retained_events_) return absl::OkStatus();
  int damaged = 0;
  return Rewrite(ReadEvents(&damaged));
}

}  // namespace semnav::reasoning
