#include "services/common/server/token_auth.h"

#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"
#include "services/common/config/secret.h"

namespace semnav {
namespace {

bool ConstantTimeEquals(absl::string_view a, absl::string_view b) {
  unsigned char diff = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff |= static_cast<unsigned char>(a[i] ^ (i < b.size() ? b[i] : 0));
  }
  return diff == 0;
}

}  // namespace

absl::StatusOr<std::vector<std::string>> LoadTokens(const AuthOptions& options) {
  std::vector<std::string> tokens;
  if (!options.token_file.empty()) {
    absl::StatusOr<std::string> content = ReadSecretFile(options.token_file);
    if (!content.ok()) return content.status();
    for (absl::string_view line : absl::StrSplit(*content, '\n', absl::SkipWhitespace())) {
      tokens.emplace_back(absl::StripAsciiWhitespace(line));
    }
  } else if (!options.token_env.empty()) {
    absl::StatusOr<std::string> token = ReadSecretEnv(options.token_env);
    if (!token.ok()) return token.status();
    tokens.push_back(*token);
  }
  return tokens;
}

grpc::Status TokenAuthProcessor::Process(const InputMetadata& auth_metadata, grpc::AuthContext*,
                                         OutputMetadata* consumed_auth_metadata, OutputMetadata*) {
  auto it = auth_metadata.find("authorization");
  if (it == auth_metadata.end()) {
    return grpc::Status(grpc::StatusCode::UNAUTHENTICATED, "missing authorization metadata");
  }
  absl::string_view value(it->second.data(), it->second.size());
  if (!absl::ConsumePrefix(&value, "Bearer ")) {
    return grpc::Status(grpc::StatusCode::UNAUTHENTICATED,
                        "authorization must be 'Bearer <token>'");
  }
  bool accepted = false;
  for (const std::string& token : tokens_) accepted |= ConstantTimeEquals(value, token);
  if (!accepted) return grpc::Status(grpc::StatusCode::UNAUTHENTICATED, "invalid token");
  consumed_auth_metadata->insert({std::string(it->first.data(), it->first.size()),
                                  std::string(it->second.data(), it->second.size())});
  return grpc::Status::OK;
}

}  // namespace semnav
