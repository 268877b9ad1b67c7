#include "services/common/cli/executable_dir.h"

#include <filesystem>

namespace semnav {

std::string ExecutableDir() {
  return std::filesystem::canonical("/proc/self/exe").parent_path().string();
}

}  // namespace semnav
