#include "services/launcher/port_check.h"

#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>

#include "absl/strings/str_cat.h"
#include "services/common/net/host_port.h"

namespace semnav::launcher {

absl::Status CheckListenAddressFree(const std::string& listen) {
  const std::optional<HostPort> address = SplitHostPort(listen);
  if (!address) return absl::OkStatus();
  const std::string host = address->BareHost();
  const std::string& port = address->port;
  addrinfo hints{};
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  if (::getaddrinfo(host.empty() ? nullptr : host.c_str(), port.c_str(), &hints, &found) != 0)
    return absl::OkStatus();
  absl::Status result = absl::OkStatus();
  const int fd = ::socket(found->ai_family, found->ai_socktype, found->ai_protocol);
  if (fd >= 0) {
    // SO_REUSEADDR: connections of a stack that just stopped (TIME_WAIT) do not count as in use.
    const int on = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof(on));
    if (::bind(fd, found->ai_addr, found->ai_addrlen) != 0 && errno == EADDRINUSE) {
      result = absl::FailedPreconditionError(absl::StrCat(listen, " is already in use"));
    }
    ::close(fd);
  }
  ::freeaddrinfo(found);
  return result;
}

}  // namespace semnav::launcher
