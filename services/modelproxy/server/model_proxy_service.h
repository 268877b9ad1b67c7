#pragma once
// gRPC adapter of semnav.modelproxy.v1.ModelProxyService (callback API). Complete and Embed
// block on vendors, so they run on a worker pool; listings answer inline.
#include <memory>
#include <string>

#include "semnav/modelproxy/v1/modelproxy.grpc.pb.h"
#include "services/common/server/worker_pool.h"
#include "services/modelproxy/core/model_proxy.h"

namespace semnav::modelproxy {

inline constexpr char kRobotIdMetadata[] = "x-semnav-robot-id";
inline constexpr char kTaskIdMetadata[] = "x-semnav-task-id";

class ModelProxyServiceImpl final : public v1::ModelProxyService::CallbackService {
 public:
  ModelProxyServiceImpl(std::unique_ptr<ModelProxy> proxy, std::string default_alias,
                        int worker_threads);

  grpc::ServerUnaryReactor* Complete(grpc::CallbackServerContext* context,
                                     const v1::CompleteRequest* request,
                                     v1::CompleteResponse* response) override;
  grpc::ServerUnaryReactor* Embed(grpc::CallbackServerContext* context,
                                  const v1::EmbedRequest* request,
                                  v1::EmbedResponse* response) override;
  grpc::ServerUnaryReactor* ListBackends(grpc::CallbackServerContext* context,
                                         const v1::ListBackendsRequest* request,
                                         v1::ListBackendsResponse* response) override;
  grpc::ServerUnaryReactor* GetUsage(grpc::CallbackServerContext* context,
                                     const v1::GetUsageRequest* request,
                                     v1::GetUsageResponse* response) override;

  // Lets queued calls finish and stops the workers (ServiceHost shutdown hook).
  void Shutdown() { workers_.Shutdown(); }

 private:
  // Runs `job` on a worker and finishes the reactor with its status.
  grpc::ServerUnaryReactor* RunOnWorker(grpc::CallbackServerContext* context,
                                        std::function<grpc::Status()> job);

  const std::unique_ptr<ModelProxy> proxy_;
  const std::string default_alias_;
  WorkerPool workers_;
};

}  // namespace semnav::modelproxy
