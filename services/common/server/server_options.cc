#include "services/common/server/server_options.h"

namespace semnav {

ServerOptions ServerOptions::FromConfig(ConfigReader& section, ServerOptions options) {
  section.Read("listen", &options.listen);
  ConfigReader tls = section.Child("tls");
  tls.Read("cert_file", &options.tls.cert_file)
      .Read("key_file", &options.tls.key_file)
      .Read("client_ca_file", &options.tls.client_ca_file);
  tls.Check(options.tls.cert_file.empty() == options.tls.key_file.empty(), "key_file",
            "cert_file and key_file must be set together");
  tls.Check(options.tls.client_ca_file.empty() || options.tls.enabled(), "client_ca_file",
            "mTLS needs cert_file and key_file too");
  ConfigReader auth = section.Child("auth");
  auth.Read("token_file", &options.auth.token_file).Read("token_env", &options.auth.token_env);
  auth.Check(options.auth.token_file.empty() || options.auth.token_env.empty(), "token_env",
             "set token_file or token_env, not both");
  section.Read("max_receive_message_mb", &options.max_receive_message_mb)
      .Read("max_send_message_mb", &options.max_send_message_mb)
      .Read("keepalive_time_s", &options.keepalive_time_s)
      .Read("keepalive_timeout_s", &options.keepalive_timeout_s)
      .Read("shutdown_grace_s", &options.shutdown_grace_s);
  section.Check(!options.listen.empty(), "listen", "must be host:port");
  section.Check(options.max_receive_message_mb >= 1 && options.max_receive_message_mb <= 1024,
                "max_receive_message_mb", "must be in [1, 1024]");
  section.Check(options.max_send_message_mb >= 1 && options.max_send_message_mb <= 1024,
                "max_send_message_mb", "must be in [1, 1024]");
  section.Check(options.keepalive_time_s >= 1, "keepalive_time_s", "must be >= 1");
  section.Check(options.keepalive_timeout_s >= 1, "keepalive_timeout_s", "must be >= 1");
  section.Check(options.shutdown_grace_s >= 0 && options.shutdown_grace_s <= 60, "shutdown_grace_s",
                "must be in [0, 60]");
  return options;
}

}  // namespace semnav
