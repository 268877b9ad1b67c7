#include "services/common/server/service_binary.h"

#include <malloc.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "absl/strings/str_cat.h"
#include "services/common/cli/flags.h"
#include "services/common/logging/log.h"
#include "services/common/net/host_port.h"

namespace semnav {
namespace {

const std::vector<FlagSpec>& Flags() {
  static const std::vector<FlagSpec> flags = {
      {"config", "FILE", "YAML config (keys: log_level, server.*, and the service section)"},
      {"listen", "HOST:PORT", "overrides server.listen"},
      {"log_level", "LEVEL", "debug, info, warning (default), error or off"},
      {"help", "", "print this help and exit"},
  };
  return flags;
}

std::string Usage(const ServiceBinarySpec& spec) {
  return absl::StrCat(
      "Usage: ", spec.binary, " [flags]\n", spec.summary, "\n\nFlags:\n", FlagsHelp(Flags()),
      "\nWith no --config every setting has its embedded default (listen ", spec.default_listen,
      ").\nServer settings (section `server:`): listen, tls.{cert_file,key_file,client_ca_file},\n"
      "auth.{token_file,token_env}, max_receive_message_mb, max_send_message_mb,\n"
      "keepalive_time_s, keepalive_timeout_s, shutdown_grace_s. Service settings: section `",
      spec.config_section, ":` (see docs/operations.md).\n");
}

int Fail(const ServiceBinarySpec& spec, const absl::Status& status, int code) {
  std::cerr << spec.binary << ": " << status.message() << "\n";
  return code;
}

}  // namespace

int RunServiceBinary(int argc, char** argv, const ServiceBinarySpec& spec) {
  // glibc gives each of gRPC's threads its own heap arena (up to 8 per core); a long-running
  // service then keeps freed memory in many half-empty arenas. Two arenas held mapping's RSS
  // flat in the fleet soak (+12 % in 4 min without). MALLOC_ARENA_MAX in the environment wins.
  if (std::getenv("MALLOC_ARENA_MAX") == nullptr) ::mallopt(M_ARENA_MAX, 2);
  // glibc raises its mmap threshold to the size of each large block freed (up to 32 MiB), so
  // the live-map snapshot's buffers of tens of MB, made every 5 s, came to live in the heap and
  // mapping's RSS followed their growing peaks. A fixed 1 MiB threshold gives such buffers back
  // to the system when freed. MALLOC_MMAP_THRESHOLD_ in the environment wins.
  if (std::getenv("MALLOC_MMAP_THRESHOLD_") == nullptr) ::mallopt(M_MMAP_THRESHOLD, 1 << 20);
  SetLogComponent(spec.binary);
  const ParsedFlags flags = ParseFlagsOrExit(argc, argv, Flags(), spec.binary, Usage(spec));

  absl::StatusOr<ConfigReader> config =
      flags.Has("config") ? ConfigReader::FromFile(*flags.Get("config")) : ConfigReader::Empty();
  if (!config.ok()) return Fail(spec, config.status(), 2);

  std::string level_name = "warning";
  config->Read("log_level", &level_name);
  if (auto flag_level = flags.Get("log_level")) level_name = *flag_level;
  absl::StatusOr<LogLevel> level = ParseLogLevel(level_name);
  if (!level.ok()) return Fail(spec, level.status(), 2);
  SetLogLevel(*level);

  ServerOptions defaults;
  defaults.listen = spec.default_listen;
  ConfigReader server_section = config->Child("server");
  ServerOptions options = ServerOptions::FromConfig(server_section, defaults);
  if (auto listen = flags.Get("listen")) options.listen = *listen;

  // Signals are taken synchronously by this thread; block them before gRPC starts its threads.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGTERM);
  sigaddset(&stop_signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  ServiceHost host(spec.binary, options);
  ConfigReader service_section = config->Child(spec.config_section);
  absl::Status setup = spec.setup(service_section, host);
  if (absl::Status settings = config->Finish(); !settings.ok()) return Fail(spec, settings, 2);
  if (!setup.ok()) return Fail(spec, setup, 2);
  if (absl::Status started = host.Start(); !started.ok()) return Fail(spec, started, 1);

  const std::optional<HostPort> listen = SplitHostPort(options.listen);
  const std::string host_part = listen ? listen->host : options.listen;
  std::cout << spec.binary << " serving on " << host_part << ":" << host.port() << std::endl;

  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  LogInfo("stopping", {{"signal", signal_number == SIGTERM ? "SIGTERM" : "SIGINT"}});
  host.Shutdown();
  return 0;
}

}  // namespace semnav
