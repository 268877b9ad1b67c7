// The launcher's stack file (services/launcher/stack_config), read from disk as `semnav up` does.
#include <cstdint>

#include "services/launcher/stack_config.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string path =
      semnav::fuzz::WriteScratchFile("stack.yaml", semnav::fuzz::AsString(data, size));
  (void)semnav::launcher::LoadStackConfig(path);
  return 0;
}
