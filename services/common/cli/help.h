#pragma once

#include <cstring>

namespace semnav {

// True when argv asks for help (--help or -h anywhere), so a tool can print its usage and
// exit 0 before doing any work.
inline bool HelpRequested(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) return true;
  }
  return false;
}

}  // namespace semnav
