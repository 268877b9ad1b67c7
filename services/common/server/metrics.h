#pragma once

#include <grpcpp/support/server_interceptor.h>

#include <array>
#include <map>
#include <memory>
#include <string>

#include "absl/synchronization/mutex.h"
#include "absl/time/time.h"
#include "semnav/common/v1/metrics.grpc.pb.h"

namespace semnav {

// Per-method call counts and latency histograms of one server process.
class MetricsRegistry {
 public:
  static constexpr std::array<double, 12> kBucketUpperMs = {0.1, 0.25, 0.5, 1,   2.5,  5,
                                                            10,  25,   50,  100, 1000, 10000};
  MetricsRegistry();
  void Record(const std::string& method, bool ok, absl::Duration latency);
  semnav::common::v1::GetMetricsResponse Snapshot(const std::string& method_prefix) const;
  void set_server_name(std::string name);

 private:
  struct Method {
    uint64_t calls = 0;
    uint64_t errors = 0;
    std::array<uint64_t, kBucketUpperMs.size() + 1> buckets{};
    double sum_ms = 0;
  };
  mutable absl::Mutex mutex_;
  std::map<std::string, Method> methods_ ABSL_GUARDED_BY(mutex_);
  std::string server_name_ ABSL_GUARDED_BY(mutex_);
  absl::Time started_;
};

// Times every RPC from its first byte to its status and records it in a registry.
class MetricsInterceptorFactory : public grpc::experimental::ServerInterceptorFactoryInterface {
 public:
  explicit MetricsInterceptorFactory(std::shared_ptr<MetricsRegistry> registry)
      : registry_(std::move(registry)) {}
  grpc::experimental::Interceptor* CreateServerInterceptor(
      grpc::experimental::ServerRpcInfo* info) override;

 private:
  std::shared_ptr<MetricsRegistry> registry_;
};

// semnav.common.v1.MetricsService over a registry.
class MetricsServiceImpl final : public semnav::common::v1::MetricsService::CallbackService {
 public:
  explicit MetricsServiceImpl(std::shared_ptr<MetricsRegistry> registry)
      : registry_(std::move(registry)) {}
  grpc::ServerUnaryReactor* GetMetrics(grpc::CallbackServerContext* context,
                                       const semnav::common::v1::GetMetricsRequest* request,
                                       semnav::common::v1::GetMetricsResponse* response) override;

 private:
  std::shared_ptr<MetricsRegistry> registry_;
};

}  // namespace semnav
