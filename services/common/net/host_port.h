#pragma once
// The one split of a "host:port" address (listen addresses, service addresses, URL authorities).
#include <optional>
#include <string>

#include "absl/strings/string_view.h"

namespace semnav {

struct HostPort {
  std::string host;  // as written: "0.0.0.0", "[::]", "" for ":50051"
  std::string port;
  // The host without IPv6 brackets ("[::1]" -> "::1"), as getaddrinfo takes it.
  std::string BareHost() const;
};

// Splits at the last ':' ("[::1]:80" -> "[::1]", "80"); nullopt when there is none.
std::optional<HostPort> SplitHostPort(absl::string_view address);

}  // namespace semnav
