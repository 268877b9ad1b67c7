#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "services/common/config/config_reader.h"

namespace semnav {

// TLS for a server. cert+key enable TLS; client_ca additionally requires and verifies
// client certificates (mTLS).
struct ServerTlsOptions {
  std::string cert_file;       // PEM server certificate chain; empty = plaintext
  std::string key_file;        // PEM private key for cert_file
  std::string client_ca_file;  // PEM CA bundle; non-empty = mTLS (client cert required)
  bool enabled() const { return !cert_file.empty(); }
};

// Bearer-token auth: clients send "authorization: Bearer <token>". One source at most.
struct AuthOptions {
  std::string token_file;  // 0600 file, one accepted token per line
  std::string token_env;   // environment variable holding one token
  bool enabled() const { return !token_file.empty() || !token_env.empty(); }
};

// The `server:` section every binary reads; defaults are the embedded localhost setup.
struct ServerOptions {
  std::string listen = "127.0.0.1:0";  // host:port; port 0 picks a free one
  ServerTlsOptions tls;
  AuthOptions auth;
  int max_receive_message_mb = 16;  // larger requests fail with RESOURCE_EXHAUSTED
  int max_send_message_mb = 16;
  int keepalive_time_s = 30;     // server pings idle connections this often
  int keepalive_timeout_s = 10;  // and drops them if a ping is not answered in time
  // After SIGTERM, in-flight calls (and idle client connections that miss the GOAWAY) get
  // this long before they are cancelled; below the 5 s an orchestrator usually allows.
  double shutdown_grace_s = 3;

  // Reads the keys of `server:`; errors land in the reader's Finish().
  static ServerOptions FromConfig(ConfigReader& section, ServerOptions defaults);
};

}  // namespace semnav
