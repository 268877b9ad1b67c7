// Every ModelProxyService request, served by the proxy as semnav-model-proxy builds it with
// default settings (the offline backend behind the default alias). See rpc_harness.h.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "services/common/config/config_reader.h"
#include "services/modelproxy/server/model_proxy_service.h"
#include "services/modelproxy/server/proxy_config.h"
#include "tests/fuzz/rpc_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace semnav::modelproxy;
  static semnav::fuzz::RpcHarness* harness = [] {
    semnav::ConfigReader section = semnav::ConfigReader::Empty();
    absl::StatusOr<BuiltProxy> built = BuildProxyFromConfig(section, ProxyOptions());
    if (!built.ok()) {
      std::fprintf(stderr, "model proxy: %s\n", built.status().ToString().c_str());
      std::abort();
    }
    std::unique_ptr<semnav::ServiceHost> host = semnav::fuzz::LoopbackHost("semnav-model-proxy");
    host->AddService(
        std::make_unique<ModelProxyServiceImpl>(std::move(built->proxy), built->default_alias,
                                                built->server.worker_threads),
        "semnav.modelproxy.v1.ModelProxyService");
    return new semnav::fuzz::RpcHarness(std::move(host),
                                        {"semnav.modelproxy.v1.ModelProxyService"});
  }();
  harness->Call(data, size);
  return 0;
}
