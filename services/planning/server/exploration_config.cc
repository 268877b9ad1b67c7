#include "services/planning/server/exploration_config.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace semnav::planning {

EroiConfig ExplorationConfig::EroiInCells(double resolution_m) const {
  EroiConfig c;
  c.eroi_size_cells = std::max(1, static_cast<int>(std::lround(eroi_size_m / resolution_m)));
  c.viewpoints_per_eroi = eroi_viewpoints;
  c.viewpoint_radius_cells = eroi_viewpoint_radius_m / resolution_m;
  c.rays = eroi_rays;
  c.ray_range_cells = eroi_ray_range_m / resolution_m;
  c.connect_radius_cells = eroi_connect_radius_m / resolution_m;
  c.lambda = eroi_lambda_per_m * resolution_m;
  c.k = eroi_k;
  c.clues_pay_extra_path = eroi_clues_pay_extra_path;
  c.min_gain_cells = static_cast<int>(std::ceil(eroi_min_gain_m2 / (resolution_m * resolution_m)));
  return c;
}

ExplorationGoalConfig ExplorationConfig::GoalConfig(double resolution_m) const {
  return {score, value, discount, coverage, EroiInCells(resolution_m)};
}

namespace {

std::vector<std::string> DiscountPlatformNames(const SemanticDiscountConfig& discount) {
  std::vector<std::string> names;
  if (discount.ground) names.push_back("ground");
  if (discount.aerial) names.push_back("aerial");
  if (discount.unspecified) names.push_back("unspecified");
  return names;
}

}  // namespace

void ExplorationConfig::Read(ConfigReader& section) {
  section.Read("min_frontier_cells", &min_frontier_cells)
      .Read("l_max_steps", &coverage.l_max_steps)
      .Read("look_clearance_m", &look_clearance_m);
  section.Check(std::isfinite(look_clearance_m) && look_clearance_m >= 0 && look_clearance_m <= 10,
                "look_clearance_m", "must be in [0, 10]");
  section.Check(min_frontier_cells >= 1, "min_frontier_cells", "must be >= 1");
  section.Check(coverage.l_max_steps >= 1, "l_max_steps", "must be >= 1");
  ConfigReader score_section = section.Child("semantic_frontier");
  score_section.Read("distance_weight", &score.distance_weight)
      .Read("novelty_weight", &score.novelty_weight)
      .Read("language_weight", &score.language_weight)
      .Read("grounding_weight", &score.grounding_weight)
      .Read("language_radius_m", &score.language_radius_m)
      .Read("novelty_radius_m", &score.novelty_radius_m);
  score_section.Check(score.novelty_radius_m > 0 && score.language_radius_m > 0, "novelty_radius_m",
                      "radii must be > 0");
  ConfigReader discount_section = section.Child("semantic_discount");
  std::vector<std::string> platforms = DiscountPlatformNames(discount);
  discount_section.Read("platforms", &platforms)
      .Read("gain", &discount.gain)
      .Read("offset_m", &discount.offset_m);
  discount.ground = discount.aerial = discount.unspecified = false;
  for (const std::string& name : platforms) {
    if (name == "ground") {
      discount.ground = true;
    } else if (name == "aerial") {
      discount.aerial = true;
    } else if (name == "unspecified") {
      discount.unspecified = true;
    } else {
      discount_section.Check(false, "platforms", "entries must be ground, aerial or unspecified");
    }
  }
  discount_section.Check(std::isfinite(discount.gain) && discount.gain >= 0 && discount.gain <= 100,
                         "gain", "must be in [0, 100]");
  discount_section.Check(
      std::isfinite(discount.offset_m) && discount.offset_m > 0 && discount.offset_m <= 100,
      "offset_m", "must be in (0, 100]");
  ConfigReader value_section = section.Child("value_map");
  value_section.Read("enabled", &value.enabled)
      .Read("evidence_sigma_m", &value.evidence_sigma_m)
      .Read("semantic_gain", &value.semantic_gain)
      .Read("gain_radius_m", &value.gain_radius_m)
      .Read("distance_decay_per_m", &value.distance_decay_per_m)
      .Read("region_link_m", &value.region_link_m)
      .Read("min_gain_m2", &value.min_gain_m2);
  value_section.Check(std::isfinite(value.evidence_sigma_m) && value.evidence_sigma_m > 0 &&
                          value.evidence_sigma_m <= 100,
                      "evidence_sigma_m", "must be in (0, 100]");
  value_section.Check(
      std::isfinite(value.gain_radius_m) && value.gain_radius_m > 0 && value.gain_radius_m <= 100,
      "gain_radius_m", "must be in (0, 100]");
  value_section.Check(
      std::isfinite(value.semantic_gain) && value.semantic_gain >= 0 && value.semantic_gain <= 100,
      "semantic_gain", "must be in [0, 100]");
  value_section.Check(std::isfinite(value.distance_decay_per_m) &&
                          value.distance_decay_per_m >= 0 && value.distance_decay_per_m <= 10,
                      "distance_decay_per_m", "must be in [0, 10]");
  value_section.Check(
      std::isfinite(value.region_link_m) && value.region_link_m >= 0 && value.region_link_m <= 100,
      "region_link_m", "must be in [0, 100]");
  value_section.Check(
      std::isfinite(value.min_gain_m2) && value.min_gain_m2 >= 0 && value.min_gain_m2 <= 1e4,
      "min_gain_m2", "must be in [0, 10000]");
  ConfigReader eroi = section.Child("eroi");
  eroi.Read("size_m", &eroi_size_m)
      .Read("viewpoints", &eroi_viewpoints)
      .Read("viewpoint_radius_m", &eroi_viewpoint_radius_m)
      .Read("rays", &eroi_rays)
      .Read("ray_range_m", &eroi_ray_range_m)
      .Read("connect_radius_m", &eroi_connect_radius_m)
      .Read("lambda_per_m", &eroi_lambda_per_m)
      .Read("k", &eroi_k)
      .Read("clues_pay_extra_path", &eroi_clues_pay_extra_path)
      .Read("min_gain_m2", &eroi_min_gain_m2);
  eroi.Check(eroi_size_m > 0 && eroi_ray_range_m > 0 && eroi_connect_radius_m > 0, "size_m",
             "EROI lengths must be > 0");
  eroi.Check(eroi_viewpoints >= 1 && eroi_rays >= 1, "viewpoints", "counts must be >= 1");
  eroi.Check(eroi_k > 0 && eroi_k <= 1, "k", "must be in (0, 1]");
  eroi.Check(std::isfinite(eroi_min_gain_m2) && eroi_min_gain_m2 >= 0 && eroi_min_gain_m2 <= 1e4,
             "min_gain_m2", "must be in [0, 10000]");
}

void TrajectoryConfig::Read(ConfigReader& section) {
  section.Read("spacing_m", &smoothing.spacing_m)
      .Read("iterations", &smoothing.iterations)
      .Read("max_speed_mps", &limits.max_speed_mps)
      .Read("max_accel_mps2", &limits.max_accel_mps2)
      .Read("max_yaw_rate_rps", &limits.max_yaw_rate_rps);
  section.Check(smoothing.spacing_m > 0, "spacing_m", "must be > 0");
  section.Check(
      limits.max_speed_mps > 0 && limits.max_accel_mps2 > 0 && limits.max_yaw_rate_rps > 0,
      "max_speed_mps", "limits must be > 0");
}

}  // namespace semnav::planning
