#include "services/common/client/channel.h"

#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>
#include <grpcpp/support/client_interceptor.h>

#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "services/common/config/secret.h"

namespace semnav {
namespace {

absl::StatusOr<std::string> ReadFile(const std::string& path, absl::string_view what) {
  std::ifstream in(path);
  if (!in) return absl::NotFoundError(absl::StrCat(what, ": cannot read '", path, "'"));
  std::stringstream content;
  content << in.rdbuf();
  return content.str();
}

// Adds "authorization: Bearer <token>" to every call. An interceptor rather than call
// credentials, so the token also travels on the plaintext loopback stack.
class BearerTokenInterceptor : public grpc::experimental::Interceptor {
 public:
  explicit BearerTokenInterceptor(const std::string* header) : header_(header) {}
  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(
            grpc::experimental::InterceptionHookPoints::PRE_SEND_INITIAL_METADATA)) {
      methods->GetSendInitialMetadata()->insert({"authorization", *header_});
    }
    methods->Proceed();
  }

 private:
  const std::string* header_;
};

class BearerTokenFactory : public grpc::experimental::ClientInterceptorFactoryInterface {
 public:
  explicit BearerTokenFactory(const std::string& token) : header_(absl::StrCat("Bearer ", token)) {}
  grpc::experimental::Interceptor* CreateClientInterceptor(
      grpc::experimental::ClientRpcInfo*) override {
    return new BearerTokenInterceptor(&header_);
  }

 private:
  std::string header_;
};

}  // namespace

ClientOptions ClientOptions::FromConfig(ConfigReader& section, ClientOptions options) {
  section.Read("address", &options.address);
  ConfigReader tls = section.Child("tls");
  tls.Read("ca_file", &options.ca_file)
      .Read("cert_file", &options.cert_file)
      .Read("key_file", &options.key_file)
      .Read("server_name", &options.server_name);
  tls.Check(options.cert_file.empty() == options.key_file.empty(), "key_file",
            "cert_file and key_file must be set together");
  ConfigReader auth = section.Child("auth");
  auth.Read("token_file", &options.token_file).Read("token_env", &options.token_env);
  section.Read("max_receive_message_mb", &options.max_receive_message_mb);
  section.Check(!options.address.empty(), "address", "must be host:port");
  return options;
}

absl::StatusOr<std::shared_ptr<grpc::Channel>> MakeChannel(const ClientOptions& options) {
  if (options.address.empty()) return absl::InvalidArgumentError("address: must be host:port");
  grpc::ChannelArguments args;
  args.SetMaxReceiveMessageSize(options.max_receive_message_mb * 1024 * 1024);
  std::shared_ptr<grpc::ChannelCredentials> credentials;
  if (!options.ca_file.empty()) {
    grpc::SslCredentialsOptions ssl;
    auto ca = ReadFile(options.ca_file, "tls.ca_file");
    if (!ca.ok()) return ca.status();
    ssl.pem_root_certs = *ca;
    if (!options.cert_file.empty()) {
      auto cert = ReadFile(options.cert_file, "tls.cert_file");
      if (!cert.ok()) return cert.status();
      auto key = ReadFile(options.key_file, "tls.key_file");
      if (!key.ok()) return key.status();
      ssl.pem_cert_chain = *cert;
      ssl.pem_private_key = *key;
    }
    if (!options.server_name.empty()) args.SetSslTargetNameOverride(options.server_name);
    credentials = grpc::SslCredentials(ssl);
  } else {
    credentials = grpc::InsecureChannelCredentials();
  }
  std::vector<std::unique_ptr<grpc::experimental::ClientInterceptorFactoryInterface>> interceptors;
  if (!options.token_file.empty() || !options.token_env.empty()) {
    absl::StatusOr<std::string> token = options.token_file.empty()
                                            ? ReadSecretEnv(options.token_env)
                                            : ReadSecretFile(options.token_file);
    if (!token.ok()) return token.status();
    interceptors.push_back(std::make_unique<BearerTokenFactory>(*token));
  }
  return grpc::experimental::CreateCustomChannelWithInterceptors(options.address, credentials, args,
                                                                 std::move(interceptors));
}
}  // namespace semnav
