#include "clients/sim/loop/remote_endpoints.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace semnav::sim::loop {
namespace {

std::string WriteYaml(const std::string& name, const std::string& yaml) {
  const std::string path =
      std::string(std::getenv("TMPDIR") ? std::getenv("TMPDIR") : "/tmp") + "/" + name;
  std::ofstream(path) << yaml;
  return path;
}

TEST(RemoteEndpointsTest, ThreePlaintextSectionsGiveThreeChannels) {
  absl::StatusOr<Endpoints> endpoints =
      LoadRemoteEndpoints(WriteYaml("plain.yaml",
                                    "gateway: {address: '10.0.0.1:50050'}\nmapping: {address: "
                                    "'127.0.0.1:50051'}\nplanning: {address: "
                                    "'10.0.0.1:50052'}\n"));
  ASSERT_TRUE(endpoints.ok()) << endpoints.status();
  EXPECT_NE(endpoints->gateway, nullptr);
  EXPECT_NE(endpoints->mapping, nullptr);
  EXPECT_NE(endpoints->planning, nullptr);
}

TEST(RemoteEndpointsTest, MissingSectionIsNamed) {
  absl::StatusOr<Endpoints> endpoints = LoadRemoteEndpoints(
      WriteYaml("no_planning.yaml", "gateway: {address: 'a:1'}\nmapping: {address: 'b:2'}\n"));
  EXPECT_EQ(endpoints.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(endpoints.status().message().find("planning"), absl::string_view::npos)
      << endpoints.status();
}

TEST(RemoteEndpointsTest, UnknownKeyIsNamed) {
  absl::StatusOr<Endpoints> endpoints =
      LoadRemoteEndpoints(WriteYaml("typo.yaml",
                                    "gateway: {address: 'a:1', tsl: {}}\nmapping: {address: "
                                    "'b:2'}\nplanning: {address: 'c:3'}\n"));
  EXPECT_EQ(endpoints.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(endpoints.status().message().find("gateway.tsl"), absl::string_view::npos)
      << endpoints.status();
}

TEST(RemoteEndpointsTest, UnreadableCertificateNamesTheSectionAndKey) {
  absl::StatusOr<Endpoints> endpoints = LoadRemoteEndpoints(WriteYaml(
      "no_ca.yaml",
      "gateway: {address: 'a:1'}\nmapping: {address: 'b:2', tls: {ca_file: /nonexistent/ca.crt}}\n"
      "planning: {address: 'c:3'}\n"));
  EXPECT_EQ(endpoints.status().code(), absl::StatusCode::kNotFound);
  EXPECT_NE(endpoints.status().message().find("mapping.tls.ca_file"), absl::string_view::npos)
      << endpoints.status();
}

}  // namespace
}  // namespace semnav::sim::loop
