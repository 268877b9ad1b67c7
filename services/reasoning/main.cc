// semnav-gateway: semantic reasoning and task orchestration (operator API + robot sessions).
#include <memory>

#include "absl/strings/str_cat.h"

#include "services/common/server/service_binary.h"
#include "services/common/client/channel.h"
#include "services/common/logging/log.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/core/conceptnet_cooccurrence.h"
#include "services/reasoning/server/mapping_watcher.h"
#include "services/reasoning/server/model_proxy_client.h"
#include "services/reasoning/server/operator_service.h"
#include "services/reasoning/server/planning_client.h"
#include "services/reasoning/server/relocalization_client.h"
#include "services/reasoning/server/robot_local_planner.h"
#include "services/reasoning/server/robot_session_service.h"

namespace {

absl::Status Setup(semnav::ConfigReader& section, semnav::ServiceHost& host) {
  using namespace semnav::reasoning;
  const GatewayConfig config = GatewayConfig::FromYaml(section);
  absl::StatusOr<Lexicon> lexicon = Lexicon::Load(config.lexicon_path);
  if (!lexicon.ok()) return lexicon.status();
  // Lexicon and planner live as long as the process; the hub refers to them.
  static const Lexicon* shared_lexicon = new Lexicon(*std::move(lexicon));
  static PathPlanner* planner = new RobotLocalPlanner();
  GatewayBackends backends;
  if (!config.planning.channel.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = semnav::MakeChannel(config.planning.channel);
    if (!channel.ok()) return channel.status();
    auto* planning = new PlanningClient(*channel, config.planning);
    planner = planning;
    backends.explorer = planning;
  }
  if (!config.model_proxy.channel.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = semnav::MakeChannel(config.model_proxy.channel);
    if (!channel.ok()) return channel.status();
    backends.model = new ModelProxyClient(*channel, config.model_proxy);
  }
  if (!config.relocalization.channel.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = semnav::MakeChannel(config.relocalization.channel);
    if (!channel.ok()) return channel.status();
    backends.relocalizer = new RelocalizationClient(*channel, config.relocalization.deadline_ms);
  }
  if (!config.prior_path.empty()) {
    absl::StatusOr<ConceptNetCooccurrence> prior = ConceptNetCooccurrence::Load(config.prior_path);
    if (prior.ok()) {
      backends.prior = new ConceptNetCooccurrence(*std::move(prior));
    } else if (config.prior_path == GatewayConfig::DefaultPriorPath()) {
      // The build-time default (the source tree's shared data) may not exist where the binary is
      // installed: explore without co-occurrence rather than not start.
      semnav::LogWarning("commonsense_prior_unavailable",
                         {{"prior_path", config.prior_path}, {"message", prior.status().message()}});
    } else {
      return absl::Status(prior.status().code(), absl::StrCat("prior_path: ", prior.status().message()));
    }
  }
  auto hub = std::make_shared<GatewayHub>(config, shared_lexicon, planner, backends);
  host.AddService(std::make_unique<OperatorServiceImpl>(hub), "semnav.reasoning.v1.OperatorService");
  host.AddService(std::make_unique<RobotSessionServiceImpl>(hub), "semnav.reasoning.v1.RobotSessionService");
  host.OnShutdown([hub] { hub->Shutdown(); });
  if (!config.mapping.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = semnav::MakeChannel(config.mapping);
    if (!channel.ok()) return channel.status();
    auto watcher = std::make_shared<MappingWatcher>(*channel, [hub](const SceneGraph& graph) { hub->OnSceneGraph(graph); });
    hub->SetSceneGraphSync([watcher](absl::Duration timeout) { return watcher->CatchUp(timeout); });
    host.OnShutdown([watcher] { watcher->Stop(); });  // runs before the hub's hook
  }
  return absl::OkStatus();
}

}  // namespace

int main(int argc, char** argv) {
  return semnav::RunServiceBinary(
      argc, argv,
      {"semnav-gateway", "semantic reasoning gateway: instructions -> subgoals -> goals -> robot commands",
       "127.0.0.1:50050", "gateway", Setup});
}
