// GatewayHub: the seed-000 open-space search loop of EROI_UTILITY tasks. Camera frames get the
// EROI codes drawn in and go to the vision model (one call per task at a time; frames meanwhile
// are dropped, motion never waits); answers update the semantic values, and region units that
// collected theta descriptions are scored by the language model. Planning's EROI_UTILITY gets the
// values with every exploration request (ContextFor).
#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/reasoning/server/camera_frame.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/request_checks.h"

namespace semnav::reasoning {

using namespace hub_internal;

absl::Status GatewayHub::OnCameraFrame(StreamSink<api::ConnectResponse>* sink,
                                       const api::CameraFrame& frame) {
  if (absl::Status s = Validate(frame); !s.ok()) return s;
  absl::MutexLock lock(&mu_);
  std::string robot_id;
  Robot* robot = RobotOfSink(sink, &robot_id);
  if (robot == nullptr || backends_.model == nullptr || shut_down_) return absl::OkStatus();
  if (robot->simulated_clock) {  // handled with the step's state, at its time
    api::ConnectRequest input;
    *input.mutable_camera() = frame;
    robot->step_inputs.push_back(std::move(input));
    return absl::OkStatus();
  }
  return HandleCameraFrame(robot_id, *robot, frame);
}

absl::Status GatewayHub::HandleCameraFrame(const std::string& robot_id, Robot& robot,
                                           const api::CameraFrame& frame) {
  if (backends_.model == nullptr || shut_down_) return absl::OkStatus();
  Task* task = tasks_.Find(robot.active_task);
  // The search prompt asks where to explore: while the task drives to, or verifies, an object it
  // located, no answer would be used before the object is confirmed or set aside.
  if (task == nullptr || task->eroi == nullptr || task->vision_busy ||
      task->executor->progress().state != TaskState::kRunning || !task->executor->exploring()) {
    return absl::OkStatus();
  }
  absl::StatusOr<DecodedCameraFrame> decoded = DecodeCameraFrame(frame);
  if (!decoded.ok()) return decoded.status();
  // Call economy: only a new view, not while backing off after a failure, within the budget.
  ModelCallPolicy& calls = task->calls;
  if (!AllowModelCall(
          *task, calls.MayAskVision(NowFor(robot_id), decoded->position, decoded->orientation))) {
    return absl::OkStatus();
  }
  const EroiObservation observation = task->eroi->Annotate(decoded->position, decoded->orientation,
                                                           decoded->camera, decoded->image);
  // ... and only a frame whose printed codes are mostly new to the model (the answer names codes).
  if (calls.MayAskCodes(task->eroi->NewCodes(observation),
                        static_cast<int>(observation.labels.size())) != CallVerdict::kAsk) {
    return absl::OkStatus();
  }
  calls.OnAskedVision(decoded->position, decoded->orientation);
  task->eroi->OnAsked(observation);
  task->vision_busy = true;
  ++task->model_calls;
  ++model_calls_;
  const std::string task_id = task->task_id;
  ModelCaller caller{robot_id, task_id};
  LanguageModel::AnswerDone done = AtSimulatedArrival<absl::StatusOr<std::string>>(
      caller, [this, task_id, prompt_tokens = EstimateTokens(observation.prompt, "", true)](
                  absl::StatusOr<std::string> answer) {
        OnVisionAnswer(task_id, std::move(answer), prompt_tokens);
      });
  backends_.model->Ask(caller, {observation.prompt, EncodePng(decoded->image)}, std::move(done));
  return absl::OkStatus();
}

void GatewayHub::OnVisionAnswer(const std::string& task_id, absl::StatusOr<std::string> answer,
                                int64_t prompt_tokens) {
  absl::MutexLock lock(&mu_);
  Task* task = tasks_.Find(task_id);
  if (shut_down_ || task == nullptr || task->eroi == nullptr) return;
  Task& t = *task;
  t.vision_busy = false;
  if (!answer.ok()) {
    // Back off: the next frame does not ask again at once (the 636-call storm).
    t.calls.OnFailure(NowFor(t.robot_id), RetryAfterSeconds(answer.status()));
    LogDebug("eroi_vision_failed", {{"task", task_id}, {"message", answer.status().message()}});
    return;
  }
  t.calls.OnAnswer(prompt_tokens + EstimateTokens("", *answer, false));
  const EroiEvidence evidence = t.eroi->OnVlmAnswer(*answer);
  LogDebug("eroi_vision_answer", {{"task", task_id},
                                  {"codes", evidence.codes_used},
                                  {"sightings", evidence.sightings},
                                  {"regions_due", evidence.due.size()}});
  for (const RegionDue& region : evidence.due) {
    if (!AllowModelCall(t, t.calls.MayAsk(NowFor(t.robot_id)))) break;
    t.calls.OnAsked();
    ++t.model_calls;
    ++model_calls_;
    ModelCaller caller{t.robot_id, task_id};
    LanguageModel::AnswerDone done = AtSimulatedArrival<absl::StatusOr<std::string>>(
        caller, [this, task_id, region](absl::StatusOr<std::string> score) {
          OnRegionScore(task_id, region, std::move(score));
        });
    backends_.model->Ask(caller, {t.eroi->RegionPrompt(region), ""}, std::move(done));
  }
}

void GatewayHub::OnRegionScore(const std::string& task_id, const RegionDue& region,
                               absl::StatusOr<std::string> answer) {
  absl::MutexLock lock(&mu_);
  Task* task = tasks_.Find(task_id);
  if (shut_down_ || task == nullptr || task->eroi == nullptr) return;
  if (answer.ok()) {
    task->calls.OnAnswer(EstimateTokens(task->eroi->RegionPrompt(region), *answer, false));
  } else {
    task->calls.OnFailure(NowFor(task->robot_id), RetryAfterSeconds(answer.status()));
  }
  const absl::Status applied =
      answer.ok() ? task->eroi->OnRegionAnswer(region, *answer) : answer.status();
  if (!applied.ok()) {
    LogDebug("eroi_region_score_unused",
             {{"task", task_id}, {"region", region.region}, {"message", applied.message()}});
  }
}

}  // namespace semnav::reasoning
