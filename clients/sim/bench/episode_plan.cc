#include "clients/sim/bench/episode_plan.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>

#include "absl/strings/str_cat.h"
#include "clients/sim/bench/target_names.h"
#include "clients/sim/core/episode_metrics.h"
#include "clients/sim/core/occupancy_raster.h"
#include "clients/sim/core/rng.h"
#include "clients/sim/loop/shortest_path.h"

namespace semnav::sim::bench {
namespace {

// A target an episode can score: reachable from the start on the body's true raster (l_i
// exists) and not already within the success radius there (l_i > 0). Object-navigation
// datasets drop the other draws the same way.
bool Scorable(const World& world, const GroundTruthGrid& grid, const StartPose& start,
              const std::string& label) {
  const Eigen::Vector2d at = start.position.head<2>();
  const SuccessRegion region = SuccessRegion::Build(world, label, grid, kDefaultSuccessRadius);
  return !region.Contains(at) && loop::NearestSuccessPoint(region, grid, at).has_value();
}

std::vector<int> StartsOf(const World& world, Modality modality) {
  std::vector<int> starts;
  for (int s = 0; s < static_cast<int>(world.starts.size()); ++s) {
    if (world.starts[s].modality == modality) starts.push_back(s);
  }
  return starts;
}

void PlanGroup(const std::vector<World>& worlds, Modality modality, int episodes, uint64_t seed,
               std::vector<loop::EpisodeSpec>& plan, std::vector<std::string>* unscorable) {
  std::vector<const World*> usable;
  for (const World& world : worlds) {
    if (!StartsOf(world, modality).empty() && !world.objects.empty()) usable.push_back(&world);
  }
  if (usable.empty()) return;
  const std::string group = ReportGroup(modality);
  const int count = static_cast<int>(usable.size());
  for (int i = 0; i < episodes; ++i) {
    const World& world = *usable[i % count];
    const std::vector<int> starts = StartsOf(world, modality);
    std::set<std::string> label_set;
    for (const ObjectInstance& o : world.objects) label_set.insert(o.label);
    const std::vector<std::string> labels(label_set.begin(), label_set.end());
    // The indoor group keeps the draw it always had, so earlier indoor numbers stay comparable.
    Rng rng(modality == Modality::kGround
                ? MixSeed(seed, static_cast<uint64_t>(i))
                : MixSeed(MixSeed(seed, static_cast<uint64_t>(modality) + 100),
                          static_cast<uint64_t>(i)));
    loop::EpisodeSpec spec;
    spec.world = world;
    spec.start_index = starts[(i / count) % starts.size()];
    const StartPose& start = world.starts[spec.start_index];
    const GroundTruthGrid grid = RasterizeOccupancy(
        world, BodyRaster(RobotConfig::ForModality(start.modality), start.position.z()));
    // Draw again while the label cannot be scored; a scorable first draw is what it always was.
    bool scorable = false;
    for (size_t attempt = 0; attempt < 4 * labels.size() && !scorable; ++attempt) {
      spec.target_label =
          labels[static_cast<size_t>(rng.UniformInt(0, static_cast<int>(labels.size()) - 1))];
      scorable = Scorable(world, grid, start, spec.target_label);
    }
    for (size_t k = 0; k < labels.size() && !scorable; ++k) {
      spec.target_label = labels[k];
      scorable = Scorable(world, grid, start, spec.target_label);
    }
    if (!scorable) {
      if (unscorable != nullptr) {
        unscorable->push_back(
            absl::StrCat(group, " episode ", i, ": ", world.name, " start ", spec.start_index,
                         ": no scorable target (every label is unreachable from the start or "
                         "already within its success region); left out"));
      }
      continue;
    }
    const std::optional<std::string> chinese = ChineseName(spec.target_label);
    spec.target = i % 4 == 3 && chinese.has_value() ? *chinese : spec.target_label;
    spec.robot_id = absl::StrCat("sim-", group, "-", i);
    spec.seed = seed + static_cast<uint64_t>(i);
    plan.push_back(std::move(spec));
  }
}

// Copies of the first `count` ground episodes for a pose-loss group.
void PlanPoseLossGroup(const std::vector<loop::EpisodeSpec>& ground, int count,
                       const std::string& group, const loop::KidnapConfig* kidnap,
                       std::vector<loop::EpisodeSpec>& plan) {
  for (int i = 0; i < count && i < static_cast<int>(ground.size()); ++i) {
    loop::EpisodeSpec spec = ground[static_cast<size_t>(i)];
    spec.sensors.odometry.enabled = true;  // the simulator's default noise (OdometryDriftConfig)
    spec.localizer.enabled = true;
    spec.landmarks = "oracle";
    spec.robot_id = absl::StrCat("sim-", group, "-", i);
    spec.report_group = group;
    if (kidnap != nullptr) spec.kidnap = *kidnap;  // the destination is drawn when it happens
    plan.push_back(std::move(spec));
  }
}

}  // namespace

std::vector<loop::EpisodeSpec> PlanEpisodes(const std::vector<World>& worlds,
                                            const EpisodeCounts& counts, uint64_t seed,
                                            std::vector<std::string>* unscorable,
                                            const loop::KidnapConfig& kidnap) {
  std::vector<loop::EpisodeSpec> plan;
  PlanGroup(worlds, Modality::kGround, counts.indoor, seed, plan, unscorable);
  if (counts.drift > 0 || counts.kidnapped > 0) {
    // The pose-loss groups rerun the indoor episodes (the same draw, so pairs line up).
    std::vector<loop::EpisodeSpec> ground;
    PlanGroup(worlds, Modality::kGround, std::max(counts.drift, counts.kidnapped), seed, ground,
              nullptr);
    PlanPoseLossGroup(ground, counts.drift, "drift", nullptr, plan);
    PlanPoseLossGroup(ground, counts.kidnapped, "kidnapped", &kidnap, plan);
  }
  PlanGroup(worlds, Modality::kUav, counts.outdoor, seed, plan, unscorable);
  PlanGroup(worlds, Modality::kFlyRoll, counts.flyroll, seed, plan, unscorable);
  return plan;
}

}  // namespace semnav::sim::bench
