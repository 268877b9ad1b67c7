// Every semnav server binary, started for real on a loopback port: the bootstrap promises of
// the foundation (health, reflection, metrics, graceful stop, config errors, TLS, tokens).
#include <gmock/gmock.h>
#include <grpcpp/create_channel.h>
#include <grpcpp/security/credentials.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "absl/time/clock.h"
#include "grpc/health/v1/health.grpc.pb.h"
#include "grpc/reflection/v1alpha/reflection.grpc.pb.h"
#include "semnav/common/v1/metrics.grpc.pb.h"
#include "tests/support/service_process.h"

namespace semnav::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::IsSupersetOf;

struct Binary {
  std::string name;
  std::string service;  // the full name its health and reflection report
};

// Test names and failure messages show the binary, not the struct's bytes.
void PrintTo(const Binary& binary, std::ostream* out) { *out << binary.name; }

const std::vector<Binary>& AllBinaries() {
  static const std::vector<Binary> binaries = {
      {"semnav-mapping", "semnav.mapping.v1.MappingService"},
      {"semnav-planning", "semnav.planning.v1.PlanningService"},
      {"semnav-relocalization", "semnav.relocalization.v1.RelocalizationService"},
      {"semnav-model-proxy", "semnav.modelproxy.v1.ModelProxyService"},
      {"semnav-gateway", "semnav.reasoning.v1.OperatorService"},
  };
  return binaries;
}

std::filesystem::path TempDir() {
  auto dir =
      std::filesystem::temp_directory_path() / ("semnav_foundation_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

std::string WriteFile(const std::string& name, const std::string& content, mode_t mode = 0600) {
  const std::string path = (TempDir() / name).string();
  std::ofstream(path) << content;
  ::chmod(path.c_str(), mode);
  return path;
}

std::vector<std::string> ReflectedServices(const std::shared_ptr<grpc::Channel>& channel) {
  using grpc::reflection::v1alpha::ServerReflection;
  auto stub = ServerReflection::NewStub(channel);
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + absl::Seconds(5)));
  auto stream = stub->ServerReflectionInfo(&context);
  grpc::reflection::v1alpha::ServerReflectionRequest request;
  request.set_list_services("*");
  stream->Write(request);
  stream->WritesDone();
  std::vector<std::string> names;
  grpc::reflection::v1alpha::ServerReflectionResponse response;
  while (stream->Read(&response)) {
    for (const auto& service : response.list_services_response().service())
      names.push_back(service.name());
  }
  EXPECT_TRUE(stream->Finish().ok());
  return names;
}

grpc::Status HealthCheck(const std::shared_ptr<grpc::Channel>& channel, const std::string& service,
                         const std::string& token = "") {
  auto stub = grpc::health::v1::Health::NewStub(channel);
  grpc::ClientContext context;
  context.set_deadline(absl::ToChronoTime(absl::Now() + absl::Seconds(3)));
  if (!token.empty()) context.AddMetadata("authorization", "Bearer " + token);
  grpc::health::v1::HealthCheckRequest request;
  request.set_service(service);
  grpc::health::v1::HealthCheckResponse response;
  return stub->Check(&context, request, &response);
}

class EveryBinaryTest : public ::testing::TestWithParam<Binary> {};

TEST_P(EveryBinaryTest, HelpDescribesFlagsAndExitsZero) {
  absl::StatusOr<ProcessResult> result = RunToCompletion(GetParam().name, {"--help"});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->exit_code, 0);
  EXPECT_THAT(result->output, HasSubstr("--config FILE"));
  EXPECT_THAT(result->output, HasSubstr("--listen HOST:PORT"));
}

TEST_P(EveryBinaryTest, ServesHealthReflectionAndMetricsThenStopsOnSigterm) {
  auto process = ServiceProcess::Start(GetParam().name);
  ASSERT_TRUE(process.ok()) << process.status();
  auto channel = (*process)->channel();
  EXPECT_TRUE(WaitForServing(channel, GetParam().service, absl::Seconds(5)).ok());
  EXPECT_THAT(ReflectedServices(channel),
              IsSupersetOf({GetParam().service, std::string("grpc.health.v1.Health"),
                            std::string("semnav.common.v1.MetricsService")}));

  auto metrics = semnav::common::v1::MetricsService::NewStub(channel);
  grpc::ClientContext context;
  semnav::common::v1::GetMetricsRequest request;
  request.set_method_prefix("/grpc.health.v1.Health/");
  semnav::common::v1::GetMetricsResponse response;
  ASSERT_TRUE(metrics->GetMetrics(&context, request, &response).ok());
  EXPECT_EQ(response.server(), GetParam().name);
  ASSERT_GE(response.methods_size(), 1);
  EXPECT_EQ(response.methods(0).method(), "/grpc.health.v1.Health/Check");
  EXPECT_GE(response.methods(0).calls(), 1u);

  const absl::Time asked = absl::Now();
  absl::StatusOr<int> exit_code = (*process)->Terminate(absl::Seconds(5));
  ASSERT_TRUE(exit_code.ok()) << exit_code.status();
  EXPECT_EQ(*exit_code, 0);
  EXPECT_LT(absl::Now() - asked, absl::Seconds(5));
}

TEST_P(EveryBinaryTest, BadConfigFailsAtStartNamingTheKey) {
  const std::string config =
      WriteFile(GetParam().name + "_bad.yaml", "server:\n  lisen: 127.0.0.1:1\n");
  absl::StatusOr<ProcessResult> result = RunToCompletion(GetParam().name, {"--config", config});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->exit_code, 2);
  EXPECT_THAT(result->output, HasSubstr("server.lisen: unknown key"));
}

INSTANTIATE_TEST_SUITE_P(Foundation, EveryBinaryTest, ::testing::ValuesIn(AllBinaries()),
                         [](const auto& info) {
                           std::string name = info.param.name.substr(7);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The security checks need one server; the bootstrap is shared by all five.
constexpr char kSecuredBinary[] = "semnav-relocalization";

TEST(SecurityTest, MissingOrWrongTokenIsUnauthenticated) {
  const std::string token_file = WriteFile("tokens", "first-token\nsecond-token\n");
  const std::string config =
      WriteFile("auth.yaml", "server:\n  auth:\n    token_file: " + token_file + "\n");
  auto process = ServiceProcess::Start(kSecuredBinary, {"--config", config}, absl::Seconds(20),
                                       /*wait_for_health=*/false);
  ASSERT_TRUE(process.ok()) << process.status();
  auto channel = (*process)->channel();
  const grpc::Status with_token = HealthCheck(channel, "", "second-token");
  EXPECT_TRUE(with_token.ok()) << with_token.error_message();
  const grpc::Status none = HealthCheck(channel, "");
  EXPECT_EQ(none.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  const grpc::Status wrong = HealthCheck(channel, "", "guessed-token");
  EXPECT_EQ(wrong.error_code(), grpc::StatusCode::UNAUTHENTICATED);
  EXPECT_THAT(wrong.error_message(), ::testing::Not(HasSubstr("first-token")));
  EXPECT_EQ(*(*process)->Terminate(), 0);
}

TEST(SecurityTest, WorldReadableTokenFileIsRefusedAtStart) {
  const std::string token_file = WriteFile("open_tokens", "tok\n", 0644);
  const std::string config =
      WriteFile("auth_open.yaml", "server:\n  auth:\n    token_file: " + token_file + "\n");
  absl::StatusOr<ProcessResult> result = RunToCompletion(kSecuredBinary, {"--config", config});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_NE(result->exit_code, 0);
  EXPECT_THAT(result->output, HasSubstr("server.auth: secret file"));
  EXPECT_THAT(result->output, HasSubstr("chmod 600"));
}

TEST(SecurityTest, TlsOnlyServerRefusesPlaintextAndServesTls) {
  const auto dir = TempDir();
  const std::string key = (dir / "server.key").string();
  const std::string cert = (dir / "server.crt").string();
  const std::string command =
      "openssl req -x509 -newkey rsa:2048 -nodes -days 2 -subj /CN=localhost -addext "
      "subjectAltName=DNS:localhost,IP:127.0.0.1 -keyout " +
      key + " -out " + cert + " 2>/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0) << "openssl is needed (deploy/install-deps.sh)";
  const std::string config = WriteFile(
      "tls.yaml", "server:\n  tls:\n    cert_file: " + cert + "\n    key_file: " + key + "\n");
  auto process = ServiceProcess::Start(kSecuredBinary, {"--config", config}, absl::Seconds(20),
                                       /*wait_for_health=*/false);
  ASSERT_TRUE(process.ok()) << process.status();
  const std::string address = (*process)->address();
  std::ifstream in(cert);
  std::stringstream pem;
  pem << in.rdbuf();
  grpc::SslCredentialsOptions ssl;
  ssl.pem_root_certs = pem.str();
  const grpc::Status tls = HealthCheck(grpc::CreateChannel(address, grpc::SslCredentials(ssl)), "");
  EXPECT_TRUE(tls.ok()) << tls.error_message();
  const grpc::Status plain = HealthCheck((*process)->channel(), "");
  EXPECT_EQ(plain.error_code(), grpc::StatusCode::UNAVAILABLE);
  EXPECT_EQ(*(*process)->Terminate(), 0);
}

}  // namespace
}  // namespace semnav::testing
