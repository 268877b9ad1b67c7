// Every OperatorService and RobotSessionService request, served by the gateway as semnav-gateway
// builds it with default settings and no mapping, planning or model proxy configured (robots
// plan locally). See rpc_harness.h for the input format.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "services/common/config/config_reader.h"
#include "services/reasoning/core/robot_local_planner.h"
#include "services/reasoning/server/gateway_config.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/operator_service.h"
#include "services/reasoning/server/robot_session_service.h"
#include "tests/fuzz/rpc_harness.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace semnav::reasoning;
  using semnav::Lexicon;
  static semnav::fuzz::RpcHarness* harness = [] {
    semnav::ConfigReader section = semnav::ConfigReader::Empty();
    GatewayConfig config = *GatewayConfig::FromYaml(section);
    config.mapping.address.clear();
    config.planning.channel.address.clear();
    config.model_proxy.channel.address.clear();
    absl::StatusOr<Lexicon> lexicon = Lexicon::Load(config.lexicon_path);
    if (!lexicon.ok()) {
      std::fprintf(stderr, "lexicon: %s\n", lexicon.status().ToString().c_str());
      std::abort();
    }
    static const Lexicon* shared_lexicon = new Lexicon(*std::move(lexicon));
    static PathPlanner* planner = new RobotLocalPlanner();
    auto hub = std::make_shared<GatewayHub>(config, shared_lexicon, planner, GatewayBackends());
    std::unique_ptr<semnav::ServiceHost> host = semnav::fuzz::LoopbackHost("semnav-gateway");
    host->AddService(std::make_unique<OperatorServiceImpl>(hub),
                     "semnav.reasoning.v1.OperatorService");
    host->AddService(std::make_unique<RobotSessionServiceImpl>(hub),
                     "semnav.reasoning.v1.RobotSessionService");
    return new semnav::fuzz::RpcHarness(
        std::move(host),
        {"semnav.reasoning.v1.OperatorService", "semnav.reasoning.v1.RobotSessionService"});
  }();
  harness->Call(data, size);
  return 0;
}
