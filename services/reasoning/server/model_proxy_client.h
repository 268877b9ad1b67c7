// LanguageModel over semnav-model-proxy (semnav.modelproxy.v1): Complete with the match_target
// and decompose tasks and their JSON schemas (docs/algorithms/modelproxy.md), Embed for target text
// embeddings. Calls run on a few worker threads with the configured deadline, so callers (the
// gateway hub, under its lock) only enqueue. After Embed fails as unavailable (the offline default
// has no embedding backend) the client answers UNAVAILABLE itself for `embedding_retry_s` instead
// of asking again. Stop() cancels calls in flight and queued ones: every `done` runs once, with
// CANCELLED then.
#pragma once

#include <grpcpp/channel.h>
#include <grpcpp/client_context.h>

#include <deque>
#include <functional>
#include <memory>
#include <set>
#include <thread>
#include <vector>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "semnav/modelproxy/v1/modelproxy.grpc.pb.h"
#include "services/reasoning/core/language_model.h"
#include "services/reasoning/server/gateway_config.h"

namespace semnav::reasoning {

class ModelProxyClient final : public LanguageModel {
 public:
  ModelProxyClient(std::shared_ptr<grpc::Channel> channel, ModelSettings settings);
  ~ModelProxyClient() override;

  void MatchTarget(const ModelCaller& caller, const ResolveRequest& request,
                   AnswerDone done) override;
  void Decompose(const ModelCaller& caller, const DecomposeRequest& request,
                 AnswerDone done) override;
  void Ask(const ModelCaller& caller, const ModelQuestion& question, AnswerDone done) override;
  void EmbedText(const ModelCaller& caller, const std::string& text, EmbeddingDone done) override;
  void Stop() override;

 private:
  // A queued call; runs on a worker with a context carrying deadline and caller metadata.
  using Job = std::function<void(grpc::ClientContext& context)>;
  void Enqueue(const ModelCaller& caller, Job job);
  // Enqueues a Complete call; `done` gets the response or the call's error.
  void Complete(const ModelCaller& caller, modelproxy::v1::CompleteRequest call,
                std::function<void(absl::StatusOr<modelproxy::v1::CompleteResponse>)> done);
  // Complete with prose, the task object as the last part and a JSON schema; `done` gets the
  // answer object as JSON text.
  void CompleteTask(const ModelCaller& caller, const std::string& prose,
                    const std::string& task_json, std::string_view schema, AnswerDone done);
  void Work();

  std::unique_ptr<modelproxy::v1::ModelProxyService::Stub> stub_;
  const ModelSettings settings_;
  absl::Mutex mu_;
  std::deque<std::pair<ModelCaller, Job>> queue_ ABSL_GUARDED_BY(mu_);
  std::set<grpc::ClientContext*> active_ ABSL_GUARDED_BY(mu_);
  absl::Time embeddings_unavailable_until_ ABSL_GUARDED_BY(mu_) = absl::InfinitePast();
  bool stopping_ ABSL_GUARDED_BY(mu_) = false;
  std::vector<std::thread> workers_;
};

}  // namespace semnav::reasoning
