// semnav-gateway: semantic reasoning and task orchestration (operator API + robot sessions).
#include <memory>

#include "absl/strings/str_cat.h"
#include "services/common/client/channel.h"
#include "services/common/logging/log.h"
#include "services/common/server/service_binary.h"
#include "services/reasoning/core/conceptnet_cooccurrence.h"
#include "services/reasoning/core/robot_local_planner.h"
#include "services/reasoning/server/gateway_hub.h"
#include "services/reasoning/server/lost_scan_client.h"
#include "services/reasoning/server/mapping_watcher.h"
#include "services/reasoning/server/model_proxy_client.h"
#include "services/reasoning/server/operator_service.h"
#include "services/reasoning/server/planning_client.h"
#include "services/reasoning/server/relocalization_client.h"
#include "services/reasoning/server/robot_session_service.h"

namespace {

using namespace semnav::reasoning;
using semnav::Lexicon;

// Everything the hub refers to, owned in one place. The hub is declared last, so it is destroyed
// first; every shared_ptr to it (services, shutdown hooks) keeps the whole stack alive.
struct GatewayStack {
  std::unique_ptr<Lexicon> lexicon;
  std::unique_ptr<RobotLocalPlanner> local_planner;   // paths without a planning service
  std::unique_ptr<PlanningClient> planning;           // null: no planning service configured
  std::unique_ptr<ModelProxyClient> model;            // null: offline default
  std::unique_ptr<ConceptNetCooccurrence> prior;      // null: explore without co-occurrence
  std::unique_ptr<RelocalizationClient> relocalizer;  // null: no relocalization loop
  std::unique_ptr<MappingLostScanClient> lost_scan;   // null: relocalization answers unrefined
  std::unique_ptr<GatewayHub> hub;
};

absl::Status Setup(semnav::ConfigReader& section, semnav::ServiceHost& host) {
  absl::StatusOr<GatewayConfig> config = GatewayConfig::FromYaml(section);
  if (!config.ok()) return config.status();
  auto stack = std::make_shared<GatewayStack>();
  absl::StatusOr<Lexicon> lexicon = Lexicon::Load(config->lexicon_path);
  if (!lexicon.ok()) return lexicon.status();
  stack->lexicon = std::make_unique<Lexicon>(*std::move(lexicon));
  stack->local_planner = std::make_unique<RobotLocalPlanner>();
  PathPlanner* planner = stack->local_planner.get();
  GatewayBackends backends;
  if (!config->planning.channel.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel =
        semnav::MakeChannel(config->planning.channel);
    if (!channel.ok()) return channel.status();
    stack->planning = std::make_unique<PlanningClient>(*channel, config->planning);
    planner = stack->planning.get();
    backends.explorer = stack->planning.get();
  }
  if (!config->model_proxy.channel.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel =
        semnav::MakeChannel(config->model_proxy.channel);
    if (!channel.ok()) return channel.status();
    stack->model = std::make_unique<ModelProxyClient>(*channel, config->model_proxy);
    backends.model = stack->model.get();
  }
  if (!config->relocalization.channel.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel =
        semnav::MakeChannel(config->relocalization.channel);
    if (!channel.ok()) return channel.status();
    stack->relocalizer =
        std::make_unique<RelocalizationClient>(*channel, config->relocalization.deadline_ms);
    backends.relocalizer = stack->relocalizer.get();
    if (!config->mapping.address.empty()) {
      absl::StatusOr<std::shared_ptr<grpc::Channel>> mapping_channel =
          semnav::MakeChannel(config->mapping);
      if (!mapping_channel.ok()) return mapping_channel.status();
      stack->lost_scan = std::make_unique<MappingLostScanClient>(
          *mapping_channel, config->relocalization.scan_match_deadline_ms);
      backends.lost_scan = stack->lost_scan.get();
    }
  }
  if (!config->prior_path.empty()) {
    absl::StatusOr<ConceptNetCooccurrence> prior = ConceptNetCooccurrence::Load(config->prior_path);
    if (prior.ok()) {
      stack->prior = std::make_unique<ConceptNetCooccurrence>(*std::move(prior));
      backends.prior = stack->prior.get();
    } else if (config->prior_path == GatewayConfig::DefaultPriorPath()) {
      // The build-time default (the source tree's shared data) may not exist where the binary is
      // installed: explore without co-occurrence rather than not start.
      semnav::LogWarning("commonsense_prior_unavailable", {{"prior_path", config->prior_path},
                                                           {"message", prior.status().message()}});
    } else {
      return absl::Status(prior.status().code(),
                          absl::StrCat("prior_path: ", prior.status().message()));
    }
  }
  const semnav::ClientOptions mapping = config->mapping;
  stack->hub =
      std::make_unique<GatewayHub>(*std::move(config), stack->lexicon.get(), planner, backends);
  const std::shared_ptr<GatewayHub> hub(stack, stack->hub.get());  // shares the stack's lifetime
  host.AddService(std::make_unique<OperatorServiceImpl>(hub),
                  "semnav.reasoning.v1.OperatorService");
  host.AddService(std::make_unique<RobotSessionServiceImpl>(hub),
                  "semnav.reasoning.v1.RobotSessionService");
  host.OnShutdown([hub] { hub->Shutdown(); });
  if (!mapping.address.empty()) {
    absl::StatusOr<std::shared_ptr<grpc::Channel>> channel = semnav::MakeChannel(mapping);
    if (!channel.ok()) return channel.status();
    auto watcher = std::make_shared<MappingWatcher>(
        *channel, [hub](const SceneGraph& graph) { hub->OnSceneGraph(graph); });
    hub->SetSceneGraphSync([watcher](absl::Duration timeout) { return watcher->CatchUp(timeout); });
    host.OnShutdown([watcher] { watcher->Stop(); });  // runs before the hub's hook
  }
  return absl::OkStatus();
}

}  // namespace

int main(int argc, char** argv) {
  semnav::ServiceBinarySpec spec;
  spec.binary = "semnav-gateway";
  spec.summary = "semantic reasoning gateway: instructions -> subgoals -> goals -> robot commands";
  spec.default_listen = "127.0.0.1:50050";
  spec.config_section = "gateway";
  spec.setup = Setup;
  return semnav::RunServiceBinary(argc, argv, spec);
}
