#include "clients/sim/bench/episode_plan.h"

#include <set>
#include <string>

#include "absl/strings/str_cat.h"
#include "clients/sim/core/rng.h"

namespace semnav::sim::bench {

std::vector<loop::EpisodeSpec> PlanEpisodes(const std::vector<World>& worlds, int episodes, uint64_t seed) {
  std::vector<const World*> usable;
  for (const World& world : worlds) {
    bool ground = false;
    for (const StartPose& s : world.starts) ground |= s.modality == Modality::kGround;
    if (ground && !world.objects.empty()) usable.push_back(&world);
  }
  std::vector<loop::EpisodeSpec> plan;
  if (usable.empty()) return plan;
  const int count = static_cast<int>(usable.size());
  for (int i = 0; i < episodes; ++i) {
    const World& world = *usable[i % count];
    std::vector<int> starts;
    for (int s = 0; s < static_cast<int>(world.starts.size()); ++s) {
      if (world.starts[s].modality == Modality::kGround) starts.push_back(s);
    }
    const std::set<std::string> label_set = [&] {
      std::set<std::string> labels;
      for (const ObjectInstance& o : world.objects) labels.insert(o.label);
      return labels;
    }();
    const std::vector<std::string> labels(label_set.begin(), label_set.end());
    Rng rng(MixSeed(seed, static_cast<uint64_t>(i)));
    loop::EpisodeSpec spec;
    spec.world = world;
    spec.start_index = starts[(i / count) % starts.size()];
    spec.target = labels[static_cast<size_t>(rng.UniformInt(0, static_cast<int>(labels.size()) - 1))];
    spec.robot_id = absl::StrCat("sim-", i);
    spec.seed = seed + static_cast<uint64_t>(i);
    plan.push_back(std::move(spec));
  }
  return plan;
}

}  // namespace semnav::sim::bench
