#pragma once

#include <string>

namespace semnav {

// Folder of the running binary: sibling binaries (services, tools) are looked up here.
std::string ExecutableDir();

}  // namespace semnav
