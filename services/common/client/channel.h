#pragma once

#include <grpcpp/channel.h>
#include <grpcpp/client_context.h>

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "services/common/config/config_reader.h"

namespace semnav {

// How one service (or client) reaches another.
struct ClientOptions {
  std::string address;    // host:port
  std::string ca_file;    // PEM CA to verify the server; empty = plaintext
  std::string cert_file;  // PEM client certificate for mTLS (with key_file)
  std::string key_file;
  std::string server_name;  // TLS name override (when the address is an IP)
  std::string token_file;   // bearer token from a 0600 file ...
  std::string token_env;    // ... or from an environment variable
  int max_receive_message_mb = 16;

  // Reads a client section (address, tls.{ca_file,cert_file,key_file,server_name},
  // auth.{token_file,token_env}, max_receive_message_mb).
  static ClientOptions FromConfig(ConfigReader& section, ClientOptions defaults);
};

// A channel with TLS/mTLS and per-call bearer-token credentials as configured.
absl::StatusOr<std::shared_ptr<grpc::Channel>> MakeChannel(const ClientOptions& options);

}  // namespace semnav
