#include "services/common/server/metrics.h"

#include <algorithm>

#include "absl/strings/match.h"
#include "absl/time/clock.h"

namespace semnav {

MetricsRegistry::MetricsRegistry() : started_(absl::Now()) {}

void MetricsRegistry::set_server_name(std::string name) {
  absl::MutexLock lock(&mutex_);
  server_name_ = std::move(name);
}

void MetricsRegistry::Record(const std::string& method, bool ok, absl::Duration latency) {
  const double ms = absl::ToDoubleMilliseconds(latency);
  const auto bucket = static_cast<std::size_t>(
      std::lower_bound(kBucketUpperMs.begin(), kBucketUpperMs.end(), ms) - kBucketUpperMs.begin());
  absl::MutexLock lock(&mutex_);
  Method& m = methods_[method];
  ++m.calls;
  if (!ok) ++m.errors;
  ++m.buckets[bucket];
  m.sum_ms += ms;
}

semnav::common::v1::GetMetricsResponse MetricsRegistry::Snapshot(
    const std::string& method_prefix) const {
  semnav::common::v1::GetMetricsResponse response;
  absl::MutexLock lock(&mutex_);
  response.set_server(server_name_);
  response.set_uptime_s(absl::ToDoubleSeconds(absl::Now() - started_));
  for (const auto& [name, m] : methods_) {
    if (!absl::StartsWith(name, method_prefix)) continue;
    auto* out = response.add_methods();
    out->set_method(name);
    out->set_calls(m.calls);
    out->set_errors(m.errors);
    for (double bound : kBucketUpperMs) out->add_bucket_upper_ms(bound);
    for (uint64_t count : m.buckets) out->add_bucket_counts(count);
    out->set_latency_sum_ms(m.sum_ms);
  }
  return response;
}

namespace {

using grpc::experimental::InterceptionHookPoints;

class MetricsInterceptor : public grpc::experimental::Interceptor {
 public:
  MetricsInterceptor(std::string method, std::shared_ptr<MetricsRegistry> registry)
      : method_(std::move(method)), registry_(std::move(registry)), start_(absl::Now()) {}

  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(InterceptionHookPoints::PRE_SEND_STATUS)) {
      registry_->Record(method_, methods->GetSendStatus().ok(), absl::Now() - start_);
    }
    methods->Proceed();
  }

 private:
  std::string method_;
  std::shared_ptr<MetricsRegistry> registry_;
  absl::Time start_;
};

}  // namespace

grpc::experimental::Interceptor* MetricsInterceptorFactory::CreateServerInterceptor(
    grpc::experimental::ServerRpcInfo* info) {
  return new MetricsInterceptor(info->method() ? info->method() : "unknown", registry_);
}

grpc::ServerUnaryReactor* MetricsServiceImpl::GetMetrics(
    grpc::CallbackServerContext* context, const semnav::common::v1::GetMetricsRequest* request,
    semnav::common::v1::GetMetricsResponse* response) {
  *response = registry_->Snapshot(request->method_prefix());
  auto* reactor = context->DefaultReactor();
  reactor->Finish(grpc::Status::OK);
  return reactor;
}

}  // namespace semnav
