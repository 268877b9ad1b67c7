// GatewayHub: task watchers, the event stream and telemetry.
#include "absl/strings/str_cat.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

void GatewayHub::WatchTask(const api::WatchTaskRequest& request,
                           StreamSink<api::WatchTaskResponse>* sink) {
  absl::MutexLock lock(&mu_);
  absl::Status valid = Validate(request);
  absl::StatusOr<Task*> found = shut_down_    ? absl::UnavailableError("gateway shutting down")
                                : !valid.ok() ? absl::StatusOr<Task*>(valid)
                                              : FindTask(request.task_id());
  if (!found.ok()) {
    sink->Close(ToGrpcStatus(found.status()));
    return;
  }
  Task& task = **found;
  if (task.revision > request.since_revision()) {
    api::WatchTaskResponse response;
    *response.mutable_task() = ReadableSnapshot(task);
    sink->Send(response);
  }
  if (task.executor->finished()) {
    sink->Close(grpc::Status::OK);
  } else {
    task_watchers_[task.task_id].insert(sink);
  }
}

void GatewayHub::UnwatchTask(StreamSink<api::WatchTaskResponse>* sink) {
  absl::MutexLock lock(&mu_);
  for (auto& [id, watchers] : task_watchers_) watchers.erase(sink);
}

void GatewayHub::WatchEvents(const api::StreamEventsRequest& request,
                             StreamSink<api::StreamEventsResponse>* sink) {
  absl::MutexLock lock(&mu_);
  if (shut_down_) {
    sink->Close(grpc::Status(grpc::StatusCode::UNAVAILABLE, "gateway shutting down"));
    return;
  }
  if (absl::Status s = Validate(request); !s.ok()) {
    sink->Close(ToGrpcStatus(s));
    return;
  }
  if (request.last_event_id() > 0) {
    bool truncated = false;
    std::vector<LoggedEvent> replay =
        events_.After(request.last_event_id(), request.robot_id(), "", &truncated);
    for (std::size_t i = 0; i < replay.size(); ++i) {
      api::StreamEventsResponse response;
      *response.mutable_event() = ToProto(replay[i]);
      response.set_replay_truncated(i == 0 && truncated);
      sink->Send(response);
    }
  }
  event_watchers_[sink] = request.robot_id();
}

void GatewayHub::UnwatchEvents(StreamSink<api::StreamEventsResponse>* sink) {
  absl::MutexLock lock(&mu_);
  event_watchers_.erase(sink);
}

absl::StatusOr<api::ListEventsResponse> GatewayHub::ListEvents(
    const api::ListEventsRequest& request) {
  if (absl::Status s = Validate(request); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  api::ListEventsResponse response;
  bool truncated = false;
  for (const LoggedEvent& event :
       events_.After(request.after_event_id(), request.robot_id(), request.task_id(), &truncated)) {
    *response.add_events() = ToProto(event);
  }
  // The log drops its oldest events first, so a task whose creation is still listed lost none.
  const bool whole_task = !request.task_id().empty() && response.events_size() > 0 &&
                          response.events(0).kind() == api::EVENT_KIND_TASK_CREATED;
  response.set_truncated(truncated && !whole_task);
  // Under the same lock as the listing, so StreamEvents from here misses nothing.
  response.set_last_event_id(events_.last_id());
  return response;
}

api::StreamSlowTelemetryResponse GatewayHub::SlowSample(const std::string& robot_id) {
  api::StreamSlowTelemetryResponse out;
  // A watcher of a robot never seen gets an empty sample; no record is created for it.
  static const Robot kUnknownRobot;
  auto found = robots_.find(robot_id);
  const Robot& robot = found != robots_.end() ? found->second : kUnknownRobot;
  out.set_session_connected(robot.session != nullptr);
  *out.mutable_capabilities() = robot.capabilities;
  if (std::optional<LeaseInfo> lease = leases_.Current(robot_id, absl::Now()))
    *out.mutable_lease() = ToProto(*lease);
  out.set_emergency_stop_active(robot.emergency_stop);
  out.set_task_id(robot.active_task);
  out.set_fast_path_resolutions(fast_resolutions_);
  out.set_slow_path_resolutions(slow_resolutions_);
  out.set_model_calls(model_calls_);
  out.set_scene_graph_revision(scene_graph_->revision);
  out.set_topological_nodes(robot.memory ? static_cast<uint32_t>(robot.memory->nodes().size()) : 0);
  *out.mutable_stamp() = ToTimestamp(absl::Now());
  if (found != robots_.end()) *out.mutable_localization() = LocalizationOf(robot);
  return out;
}

void GatewayHub::WatchFastTelemetry(const api::StreamFastTelemetryRequest& request,
                                    StreamSink<api::StreamFastTelemetryResponse>* sink) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) {
    sink->Close(ToGrpcStatus(s));
    return;
  }
  if (shut_down_ || request.robot_id().empty() || request.max_rate_hz() > 50) {
    sink->Close(ToGrpcStatus(
        shut_down_ ? absl::UnavailableError("gateway shutting down")
                   : FieldError(absl::StatusCode::kInvalidArgument,
                                request.robot_id().empty() ? "robot_id" : "max_rate_hz",
                                request.robot_id().empty() ? "is required" : "must be 1 to 50")));
    return;
  }
  const uint32_t rate = request.max_rate_hz() == 0 ? 10 : request.max_rate_hz();
  fast_watchers_.Add(sink, request.robot_id(), absl::Seconds(1.0 / rate));
}

void GatewayHub::UnwatchFastTelemetry(StreamSink<api::StreamFastTelemetryResponse>* sink) {
  absl::MutexLock lock(&mu_);
  fast_watchers_.Remove(sink);
}

void GatewayHub::WatchSlowTelemetry(const api::StreamSlowTelemetryRequest& request,
                                    StreamSink<api::StreamSlowTelemetryResponse>* sink) {
  absl::MutexLock lock(&mu_);
  if (absl::Status s = Validate(request); !s.ok()) {
    sink->Close(ToGrpcStatus(s));
    return;
  }
  absl::Duration period = absl::Seconds(1);
  if (request.has_period())
    period = absl::Milliseconds(TimeUtil::DurationToMilliseconds(request.period()));
  if (shut_down_ || request.robot_id().empty() || period < absl::Milliseconds(100)) {
    sink->Close(ToGrpcStatus(
        shut_down_ ? absl::UnavailableError("gateway shutting down")
                   : FieldError(absl::StatusCode::kInvalidArgument,
                                request.robot_id().empty() ? "robot_id" : "period",
                                request.robot_id().empty() ? "is required" : "must be >= 100 ms")));
    return;
  }
  slow_watchers_.Add(sink, request.robot_id(), period);
}

void GatewayHub::UnwatchSlowTelemetry(StreamSink<api::StreamSlowTelemetryResponse>* sink) {
  absl::MutexLock lock(&mu_);
  slow_watchers_.Remove(sink);
}

}  // namespace semnav::reasoning
