#include "services/launcher/free_port.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <fstream>
#include <random>

namespace semnav::launcher {
namespace {

// Binds `port` on loopback (0 = the kernel's choice); the port bound, or 0 when it is taken.
int TryBind(int port) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return 0;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  socklen_t length = sizeof(address);
  const bool ok = ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0 &&
                  ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) == 0;
  ::close(fd);
  return ok ? ntohs(address.sin_port) : 0;
}

// The first port of the kernel's ephemeral range (outgoing connections draw from it).
int EphemeralStart() {
  std::ifstream range("/proc/sys/net/ipv4/ip_local_port_range");
  int low = 32768;
  range >> low;
  return range ? low : 32768;
}

}  // namespace

absl::StatusOr<int> FreeLoopbackPort() {
  // Below the ephemeral range: a port handed out there can be taken by any outgoing connection
  // before the service binds it (a parallel ctest run lost a model proxy's port that way).
  constexpr int kLowest = 10000;
  const int end = EphemeralStart();
  if (end - kLowest >= 1000) {
    static std::atomic<uint32_t> calls{0};
    std::mt19937 random(static_cast<uint32_t>(::getpid()) * 2654435761u + calls++);
    std::uniform_int_distribution<int> pick(kLowest, end - 1);
    for (int attempt = 0; attempt < 64; ++attempt) {
      if (const int port = TryBind(pick(random)); port != 0) return port;
    }
  }
  if (const int port = TryBind(0); port != 0) return port;
  return absl::InternalError("could not find a free loopback port");
}

}  // namespace semnav::launcher
