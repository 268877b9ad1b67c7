#pragma once

#include <grpcpp/security/auth_metadata_processor.h>

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "services/common/server/server_options.h"

namespace semnav {

// The accepted bearer tokens from the configured source (file lines or one env var).
absl::StatusOr<std::vector<std::string>> LoadTokens(const AuthOptions& options);

// Accepts a call only with "authorization: Bearer <token>" for one of the tokens; otherwise
// UNAUTHENTICATED. Tokens are compared in constant time and never logged.
class TokenAuthProcessor : public grpc::AuthMetadataProcessor {
 public:
  explicit TokenAuthProcessor(std::vector<std::string> tokens) : tokens_(std::move(tokens)) {}
  bool IsBlocking() const override { return false; }
  grpc::Status Process(const InputMetadata& auth_metadata, grpc::AuthContext* context,
                       OutputMetadata* consumed_auth_metadata,
                       OutputMetadata* response_metadata) override;

 private:
  std::vector<std::string> tokens_;
};

}  // namespace semnav
