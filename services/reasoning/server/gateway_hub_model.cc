// GatewayHub: the slow path over the model proxy (asynchronous: the robot keeps exploring while
// the model thinks, seed 000 3.5), target text embeddings, and the exploration context.
#include "absl/strings/str_cat.h"
#include "services/common/logging/log.h"
#include "services/reasoning/core/selective_grounding.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/hub_internal.h"
#include "services/reasoning/server/proto_convert.h"

namespace semnav::reasoning {

using namespace hub_internal;

namespace {

// A slow-path answer (or the call's error) as the executor's decision; failures keep exploring
// (the executor re-asks on a newer graph).
SlowDecision DecideSlow(const absl::StatusOr<std::string>& answer, const ModelRequest& request,
                        const SlowPathConfig& config) {
  SlowDecision decision;
  if (!answer.ok()) {
    decision.explanation = absl::StrCat("model call failed: ", answer.status().message());
  } else if (absl::StatusOr<SlowDecision> parsed =
                 ParseResolveAnswer(*answer, request.grounded, config);
             parsed.ok()) {
    decision = *std::move(parsed);
  } else {
    decision.explanation = absl::StrCat("model answer rejected: ", parsed.status().message());
  }
  return decision;
}

}  // namespace

// --- Call economy (issue 15; ModelCallPolicy) ------------------------------------------------
bool GatewayHub::AllowModelCall(Task& task, CallVerdict verdict) {
  if (verdict == CallVerdict::kBudgetSpent && task.calls.TakeBudgetSpentNotice()) {
    Log(api::EVENT_KIND_MODEL_BUDGET, task.robot_id, task.task_id,
        absl::StrCat("model budget spent (", task.calls.calls(), " calls, ", task.calls.tokens(),
                     " tokens): continuing without the model"));
  }
  return verdict == CallVerdict::kAsk;
}

void GatewayHub::DispatchModelRequest(Task& task) {
  if (backends_.model == nullptr || shut_down_) return;
  std::optional<ModelRequest> request = task.executor->TakeModelRequest();
  if (!request.has_value()) return;
  // Call economy: a question already answered is answered from the task's cache; none is asked
  // while backing off or over budget (the executor keeps exploring and asks on a newer graph).
  std::optional<absl::StatusOr<std::string>> settled =
      task.calls.CachedSlowAnswer(request->request.task_json);
  if (const CallVerdict verdict = task.calls.MayAsk(NowFor(task.robot_id));
      !settled.has_value() && !AllowModelCall(task, verdict)) {
    settled =
        absl::ResourceExhaustedError(absl::StrCat("not asked (", CallVerdictName(verdict), ")"));
  }
  if (settled.has_value()) {
    const std::vector<RobotCommand> commands =
        task.executor->OnSlowDecision(NowFor(task.robot_id), request->graph_revision,
                                      DecideSlow(*settled, *request, config_.slow_path));
    if (!commands.empty()) Apply(task, commands);
    return;
  }
  task.calls.OnAsked();
  ++task.model_calls;
  ++model_calls_;
  const std::string task_id = task.task_id;
  const uint64_t generation = task.executor_generation;
  auto shared = std::make_shared<const ModelRequest>(*std::move(request));
  ModelCaller caller{task.robot_id, task_id};
  LanguageModel::AnswerDone done = AtSimulatedArrival<absl::StatusOr<std::string>>(
      caller, [this, task_id, generation, shared](absl::StatusOr<std::string> answer) {
        OnModelAnswer(task_id, generation, *shared, std::move(answer));
      });
  backends_.model->MatchTarget(caller, shared->request, std::move(done));
}

void GatewayHub::OnModelAnswer(const std::string& task_id, uint64_t generation,
                               const ModelRequest& request, absl::StatusOr<std::string> answer) {
  absl::MutexLock lock(&mu_);
  Task* task = tasks_.Find(task_id);
  if (task == nullptr) return;
  AwaitExecutor(*task);
  // An answer for the rule plan's executor after the model's plan replaced it is not for this one.
  if (shut_down_ || task->executor_generation != generation) return;
  if (answer.ok()) {
    task->calls.OnAnswer(
        EstimateTokens(request.request.prose + request.request.task_json, *answer, false));
    task->calls.StoreSlowAnswer(request.request.task_json, *answer);
  } else {
    task->calls.OnFailure(NowFor(task->robot_id), RetryAfterSeconds(answer.status()));
  }
  const SlowDecision decision = DecideSlow(answer, request, config_.slow_path);
  LogDebug("slow_path_answer",
           {{"task", task_id},
            {"action", decision.action == SlowAction::kGoal           ? "goal"
                       : decision.action == SlowAction::kVisionVerify ? "verify"
                                                                      : "explore"},
            {"object", decision.object_id},
            {"confidence", decision.confidence},
            {"explanation", decision.explanation}});
  Apply(*task,
        task->executor->OnSlowDecision(NowFor(task->robot_id), request.graph_revision, decision));
}

// Seed 000 3.5 / the issue: the model never blocks motion. The task starts on the rule subgoals
// at once; a valid model plan that arrives while the task is still running replaces them (the
// call's deadline bounds how much rule progress that discards; the robot gets the new plan's
// first command), anything else keeps the rules.
void GatewayHub::RequestDecomposition(Task& task, Decomposition rules) {
  task.calls.OnAsked();
  ++task.model_calls;
  ++model_calls_;
  const std::string task_id = task.task_id;
  auto shared = std::make_shared<const Decomposition>(std::move(rules));
  ModelCaller caller{task.robot_id, task_id};
  LanguageModel::AnswerDone done = AtSimulatedArrival<absl::StatusOr<std::string>>(
      caller, [this, task_id, shared](absl::StatusOr<std::string> answer) {
        OnDecomposition(task_id, *shared, std::move(answer));
      });
  backends_.model->Decompose(caller, BuildDecomposeRequest(task.instruction), std::move(done));
}

Decomposition GatewayHub::DecomposeBeforeRefusing(const std::string& robot_id,
                                                  const std::string& instruction,
                                                  Decomposition rules) {
  struct Pending {
    absl::Mutex mu;
    bool done = false;
    absl::StatusOr<std::string> answer = absl::DeadlineExceededError("no answer in time");
  };
  auto pending = std::make_shared<Pending>();
  ++model_calls_;
  backends_.model->Decompose(ModelCaller{robot_id, ""}, BuildDecomposeRequest(instruction),
                             [pending](absl::StatusOr<std::string> answer) {
                               absl::MutexLock lock(&pending->mu);
                               pending->answer = std::move(answer);
                               pending->done = true;
                             });
  absl::StatusOr<std::string> answer = absl::DeadlineExceededError("no answer in time");
  mu_.Unlock();
  {
    // The client ends every call by its deadline (CANCELLED when stopped); the margin only
    // guards against a model that never calls back.
    absl::MutexLock lock(&pending->mu);
    pending->mu.AwaitWithTimeout(
        absl::Condition(&pending->done),
        absl::Milliseconds(config_.model_proxy.deadline_ms) + absl::Seconds(1));
    answer = pending->answer;
  }
  mu_.Lock();
  Decomposition chosen = rules;
  if (answer.ok()) {
    chosen = decomposer_->WithModelAnswer(rules, *answer);
  } else {
    chosen.rejection = absl::StrCat("model call failed: ", answer.status().message());
  }
  if (chosen.source == "model")
    chosen.subgoals = decomposer_->CompleteFinds(std::move(chosen.subgoals));
  LogInfo("open_vocabulary_decomposition", {{"robot", robot_id},
                                            {"source", chosen.source},
                                            {"subgoals", DescribeSubgoals(chosen.subgoals)},
                                            {"rejection", chosen.rejection}});
  return chosen;
}

void GatewayHub::OnDecomposition(const std::string& task_id, const Decomposition& rules,
                                 absl::StatusOr<std::string> answer) {
  absl::MutexLock lock(&mu_);
  Task* found = tasks_.Find(task_id);
  if (found == nullptr) return;
  AwaitExecutor(*found);  // the executor is replaced below
  if (shut_down_) return;
  Task& task = *found;
  Decomposition chosen = rules;
  if (answer.ok()) {
    chosen = decomposer_->WithModelAnswer(rules, *answer);
  } else {
    chosen.rejection = absl::StrCat("model call failed: ", answer.status().message());
  }
  const TaskState state = task.executor->progress().state;
  if (chosen.source == "model" && state != TaskState::kRunning) {
    chosen = rules;
    chosen.rejection =
        absl::StrCat("the model's plan came when the task was ", std::string(TaskStateName(state)));
  }
  LogDebug("decomposition",
           {{"task", task_id}, {"source", chosen.source}, {"rejection", chosen.rejection}});
  if (chosen.source != "model") {
    Log(api::EVENT_KIND_DECOMPOSITION, task.robot_id, task_id,
        absl::StrCat("rules kept: ", chosen.rejection));
    return;
  }
  Log(api::EVENT_KIND_DECOMPOSITION, task.robot_id, task_id,
      absl::StrCat("model subgoals used: ", DescribeSubgoals(chosen.subgoals)));
  task.source = chosen.source;
  InstallExecutor(task, std::move(chosen.subgoals));
  task.started = false;
  StartIfPossible(task);
}

void GatewayHub::RequestTextEmbedding(Task& task) {
  if (backends_.model == nullptr || !config_.model_proxy.text_embeddings) return;
  const TargetSpec* target = PrimaryTarget(task.executor->subgoals());
  if (target == nullptr || target->is_room) return;
  ++task.model_calls;
  ++model_calls_;
  const std::string task_id = task.task_id;
  ModelCaller caller{task.robot_id, task_id};
  LanguageModel::EmbeddingDone done = AtSimulatedArrival<absl::StatusOr<std::vector<float>>>(
      caller, [this, task_id](absl::StatusOr<std::vector<float>> embedding) {
        OnTextEmbedding(task_id, std::move(embedding));
      });
  backends_.model->EmbedText(caller, target->text.empty() ? target->name : target->text,
                             std::move(done));
}

void GatewayHub::OnTextEmbedding(const std::string& task_id,
                                 absl::StatusOr<std::vector<float>> embedding) {
  absl::MutexLock lock(&mu_);
  Task* task = tasks_.Find(task_id);
  if (task == nullptr) return;
  AwaitExecutor(*task);
  if (shut_down_) return;
  if (!embedding.ok()) {
    // The seed's fallback stays: the label match stands in for the embedding term.
    LogDebug("text_embedding_unavailable",
             {{"task", task_id}, {"message", embedding.status().message()}});
    return;
  }
  task->executor->SetTextEmbedding(*std::move(embedding));
  Apply(*task, GiveSceneGraph(*task, NowFor(task->robot_id)));
}

bool GatewayHub::WantsSlowPath(const api::ResolveTargetRequest& request,
                               const api::ResolveTargetResponse& fast) const {
  return request.allow_slow_path() && !fast.has_target() && backends_.model != nullptr;
}

void GatewayHub::ResolveSlow(const api::ResolveTargetRequest& request,
                             api::ResolveTargetResponse fast,
                             std::function<void(absl::StatusOr<api::ResolveTargetResponse>)> done) {
  absl::MutexLock lock(&mu_);
  if (shut_down_) {
    done(absl::UnavailableError("gateway shutting down"));
    return;
  }
  const TargetSpec target = FromProto(fast.understood());
  GroundingConfig grounding;
  grounding.max_objects = config_.executor.grounding_max_objects;
  auto grounded = std::make_shared<const SceneGraph>(
      SelectiveGrounding(target, *scene_graph_, matcher_, grounding).graph);
  fast.set_grounded_objects(static_cast<int>(grounded->objects.size()));
  if (grounded->objects.empty()) {
    fast.set_explanation("slow path not run: the scene graph has nothing to ground the target on");
    done(std::move(fast));
    return;
  }
  ++model_calls_;
  const ResolveRequest call = BuildResolveRequest(request.text(), target, *grounded);
  backends_.model->MatchTarget(
      {request.robot_id(), ""}, call,
      [this, grounded, fast = std::move(fast),
       done = std::move(done)](absl::StatusOr<std::string> answer) mutable {
        if (!answer.ok()) {
          done(answer.status());
          return;
        }
        const absl::StatusOr<SlowDecision> decision =
            ParseResolveAnswer(*answer, *grounded, config_.slow_path);
        if (!decision.ok()) {
          done(absl::Status(decision.status().code(),
                            absl::StrCat("model answer: ", decision.status().message())));
          return;
        }
        fast.set_explanation(decision->explanation);
        if (decision->action == SlowAction::kGoal) {
          const SceneObject* object = grounded->FindObject(decision->object_id);
          api::ResolvedTarget* resolved = fast.mutable_target();
          resolved->set_object_id(object->id);
          resolved->mutable_position()->set_x(object->position.x());
          resolved->mutable_position()->set_y(object->position.y());
          resolved->mutable_position()->set_z(object->position.z());
          resolved->set_confidence(decision->confidence);
          resolved->set_path(api::RESOLUTION_PATH_SLOW);
          resolved->set_label(object->label);
        }
        done(std::move(fast));
      });
}

ExplorationContext GatewayHub::ContextFor(const std::string& task_id) {
  Task* task = tasks_.Find(task_id);
  if (task == nullptr) return {};
  const TargetSpec* target = PrimaryTarget(task->executor->subgoals());
  const Robot& robot = RobotRecord(task->robot_id);
  ExplorationContext context =
      BuildExplorationContext(target != nullptr ? *target : TargetSpec{}, *scene_graph_, matcher_,
                              backends_.prior, robot.memory.get());
  if (const EroiSearch* search = task->eroi.get(); search != nullptr) {
    context.eroi_values = search->PlanarValues();
    context.eroi_window_min = search->WindowMin();
    context.eroi_window_max = search->WindowMax();
    context.eroi_edge_m = search->grid().spec().delta;
    context.eroi_sightings = search->sightings();
    context.eroi_inspect_distance_m = search->inspect_distance_m();
  }
  context.search_area = task->search_area;
  return context;
}

}  // namespace semnav::reasoning
