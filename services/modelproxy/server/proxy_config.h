#pragma once
// Builds the proxy from the `modelproxy:` YAML section. Without any settings the proxy has one
// backend, "offline" (the ConceptNet prior), and alias "default" -> [offline]: the embedded,
// key-free setup `semnav up` runs. Keys come only from api_key_env / api_key_file (0600).
#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "services/common/config/config_reader.h"
#include "services/modelproxy/core/model_proxy.h"

namespace semnav::modelproxy {

struct ServerSettings {
  int worker_threads = 64;  // concurrent Complete/Embed calls being served
};

struct BuiltProxy {
  std::unique_ptr<ModelProxy> proxy;
  ServerSettings server;
  std::string default_alias;
};

// Reads every key of `section` (errors are recorded on it and also returned). `options`
// supplies the failure-event hook; its other fields are overwritten from the config.
absl::StatusOr<BuiltProxy> BuildProxyFromConfig(ConfigReader& section, ProxyOptions options);

}  // namespace semnav::modelproxy
