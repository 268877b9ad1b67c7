// The model proxy's offline backend reads the gateway's task objects (match_target with
// candidates taken from the scene graph, rank_regions): services/modelproxy/core/offline.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "nlohmann/json.hpp"
#include "services/common/place_prior/place_prior.h"
#include "services/modelproxy/core/offline/offline_tasks.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace semnav::modelproxy::offline;
  using semnav::PlacePrior;
  static const PlacePrior* prior = [] {
    absl::StatusOr<PlacePrior> loaded = PlacePrior::Load(PlacePrior::DefaultPath());
    if (!loaded.ok()) {
      std::fprintf(stderr, "offline prior: %s\n", std::string(loaded.status().message()).c_str());
      std::abort();
    }
    return new PlacePrior(*std::move(loaded));
  }();
  const nlohmann::json task =
      nlohmann::json::parse(data, data + size, nullptr, /*allow_exceptions=*/false);
  if (task.is_discarded()) return 0;
  (void)RunOfflineTask(task, *prior, OfflineParams());
  return 0;
}
