#include "services/reasoning/server/gateway_config.h"

#include <cmath>

#include "services/common/place_prior/place_prior.h"
#include "services/common/status/field_error.h"
#include "services/reasoning/core/input_limits.h"

namespace semnav::reasoning {

std::string GatewayConfig::DefaultPriorPath() { return PlacePrior::DefaultPath(); }

EroiSearchConfig DefaultEroiSearch() {
  EroiSearchConfig search;
  search.grid.delta = 2.0;
  return search;
}

absl::StatusOr<GatewayConfig> GatewayConfig::FromYaml(ConfigReader& section) {
  GatewayConfig c;
  ConfigReader decomposer = section.Child("decomposer");
  decomposer.Read("approach_distance_m", &c.decomposer.approach_distance_m)
      .Read("max_simple_unknown_words", &c.decomposer.max_simple_unknown_words);
  decomposer.Check(c.decomposer.approach_distance_m > 0.0, "approach_distance_m", "must be > 0");

  ConfigReader fast = section.Child("fast_path");
  fast.Read("label_weight", &c.fast_path.label_weight)
      .Read("embedding_weight", &c.fast_path.embedding_weight)
      .Read("detector_weight", &c.fast_path.detector_weight)
      .Read("spatial_weight", &c.fast_path.spatial_weight)
      .Read("fast_threshold", &c.fast_path.fast_threshold)
      .Read("detection_count_saturation", &c.fast_path.detection_count_saturation)
      .Read("unknown_colour_factor", &c.fast_path.unknown_colour_factor);
  fast.Check(c.fast_path.detection_count_saturation > 0, "detection_count_saturation",
             "must be > 0");
  fast.Check(c.fast_path.fast_threshold >= 0.0 && c.fast_path.fast_threshold <= 1.0,
             "fast_threshold", "must be in [0, 1]");

  ConfigReader slow = section.Child("slow_path");
  slow.Read("confidence_threshold", &c.slow_path.confidence_threshold)
      .Read("vision_threshold", &c.slow_path.vision_threshold)
      .Read("vision_enabled", &c.slow_path.vision_enabled)
      .Read("offline_confidence_factor", &c.slow_path.offline_confidence_factor);

  ConfigReader executor = section.Child("executor");
  executor.Read("approach_speed_mps", &c.executor.approach_speed_mps)
      .Read("look_around_rate_rps", &c.executor.look_around_rate_rps)
      .Read("look_around_duration_s", &c.executor.look_around_duration_s)
      .Read("explore_scan_duration_s", &c.executor.explore_scan_duration_s)
      .Read("start_scan_duration_s", &c.executor.start_scan_duration_s)
      .Read("look_up_labels", &c.executor.look_up_labels)
      .Read("look_up_tilt_rad", &c.executor.look_up_tilt_rad)
      .Read("look_up_every_m", &c.executor.look_up_every_m)
      .Read("navigate_standoff_m", &c.executor.navigate_standoff_m)
      .Read("navigate_timeout_s", &c.executor.navigate_timeout_s)
      .Read("verify_timeout_s", &c.executor.verify_timeout_s)
      .Read("verify_detections", &c.executor.verify_detections)
      .Read("wait_duration_s", &c.executor.wait_duration_s)
      .Read("success_radius_m", &c.executor.success_radius_m)
      .Read("reach_extent_cap_m", &c.executor.reach_extent_cap_m)
      .Read("max_replans", &c.executor.max_replans)
      .Read("max_explore_goals", &c.executor.max_explore_goals)
      .Read("explore_exclusion_radius_m", &c.executor.explore_exclusion_radius_m)
      .Read("path_clearance_m", &c.executor.path_clearance_m)
      .Read("min_explore_step_m", &c.executor.min_explore_step_m)
      .Read("fallback_explore_step_m", &c.executor.fallback_explore_step_m)
      .Read("no_path_retreat_m", &c.executor.no_path_retreat_m)
      .Read("explore_reselect_s", &c.executor.explore_reselect_s)
      .Read("explore_keep_radius_m", &c.executor.explore_keep_radius_m)
      .Read("explore_with_footprint", &c.executor.explore_with_footprint)
      .Read("grounding_max_objects", &c.executor.grounding_max_objects)
      .Read("dependency_retry_s", &c.executor.dependency_retry_s)
      .Read("dependency_timeout_s", &c.executor.dependency_timeout_s)
      .Read("progress_timeout_s", &c.executor.progress_timeout_s)
      .Read("progress_distance_m", &c.executor.progress_distance_m)
      .Read("success_margin_m", &c.executor.success_margin_m)
      .Read("verify_accept_detections", &c.executor.verify_accept_detections)
      .Read("verify_view_m", &c.executor.verify_view_m)
      .Read("verify_rule_out_misses", &c.executor.verify_rule_out_misses)
      .Read("backoff_m", &c.executor.backoff_m)
      .Read("blocked_clearance_step_m", &c.executor.blocked_clearance_step_m)
      .Read("blocked_clearance_max_m", &c.executor.blocked_clearance_max_m)
      .Read("max_blocks_per_goal", &c.executor.max_blocks_per_goal)
      .Read("blocked_spot_radius_m", &c.executor.blocked_spot_radius_m)
      .Read("look_around_after_blocks_at_spot", &c.executor.look_around_after_blocks_at_spot)
      .Read("max_contacts", &c.executor.max_contacts)
      .Read("unreachable_region_m", &c.executor.unreachable_region_m)
      .Read("time_budget_s", &c.executor.time_budget_s)
      .Read("endgame_s", &c.executor.endgame_s)
      .Read("approach_label_match", &c.executor.approach_label_match)
      .Read("min_appearance_agreement", &c.executor.min_appearance_agreement)
      .Read("glance_s", &c.executor.glance_s);
  executor.Check(
      c.executor.explore_scan_duration_s >= 0.0 && c.executor.explore_scan_duration_s <= 120.0,
      "explore_scan_duration_s", "must be in [0, 120] (0 = no turn)");
  executor.Check(
      c.executor.start_scan_duration_s >= 0.0 && c.executor.start_scan_duration_s <= 120.0,
      "start_scan_duration_s", "must be in [0, 120] (0 = no turn)");
  executor.Check(std::isfinite(c.executor.look_up_tilt_rad) && c.executor.look_up_tilt_rad >= 0.0 &&
                     c.executor.look_up_tilt_rad <= kMaxCameraTiltRad,
                 "look_up_tilt_rad", "must be in [0, pi/2] (0 = never)");
  executor.Check(std::isfinite(c.executor.look_up_every_m) && c.executor.look_up_every_m >= 0.0 &&
                     c.executor.look_up_every_m <= 1000.0,
                 "look_up_every_m", "must be in [0, 1000]");
  executor.Check(c.executor.look_up_labels.size() <= 64, "look_up_labels", "at most 64 labels");
  executor.Check(c.executor.success_radius_m > 0.0, "success_radius_m", "must be > 0");
  executor.Check(c.executor.max_replans >= 0, "max_replans", "must be >= 0");
  executor.Check(c.executor.explore_exclusion_radius_m >= 0.0, "explore_exclusion_radius_m",
                 "must be >= 0");
  executor.Check(std::isfinite(c.executor.explore_reselect_s) &&
                     c.executor.explore_reselect_s >= 0.0 && c.executor.explore_reselect_s <= 600.0,
                 "explore_reselect_s", "must be in [0, 600] (0 = off)");
  executor.Check(std::isfinite(c.executor.explore_keep_radius_m) &&
                     c.executor.explore_keep_radius_m >= 0.0 &&
                     c.executor.explore_keep_radius_m <= 50.0,
                 "explore_keep_radius_m", "must be in [0, 50]");
  executor.Check(c.executor.path_clearance_m >= 0.0, "path_clearance_m", "must be >= 0");
  executor.Check(c.executor.dependency_retry_s > 0.0, "dependency_retry_s", "must be > 0");
  executor.Check(c.executor.dependency_timeout_s >= c.executor.dependency_retry_s,
                 "dependency_timeout_s", "must be >= dependency_retry_s");
  executor.Check(c.executor.verify_timeout_s > 0.0, "verify_timeout_s", "must be > 0");
  executor.Check(c.executor.progress_timeout_s > 0.0, "progress_timeout_s", "must be > 0");
  executor.Check(c.executor.progress_distance_m > 0.0, "progress_distance_m", "must be > 0");
  executor.Check(c.executor.success_margin_m >= 0.0 &&
                     c.executor.success_margin_m < c.executor.success_radius_m,
                 "success_margin_m", "must be in [0, success_radius_m)");
  executor.Check(std::isfinite(c.executor.reach_extent_cap_m) &&
                     c.executor.reach_extent_cap_m >= 0.0 && c.executor.reach_extent_cap_m <= 5.0,
                 "reach_extent_cap_m", "must be in [0, 5]");
  executor.Check(c.executor.verify_accept_detections >= 1, "verify_accept_detections",
                 "must be >= 1");
  executor.Check(
      c.executor.verify_view_m > 0.0 && c.executor.verify_view_m <= c.executor.success_radius_m,
      "verify_view_m", "must be in (0, success_radius_m]");
  executor.Check(
      c.executor.verify_rule_out_misses >= 0 && c.executor.verify_rule_out_misses <= 1000,
      "verify_rule_out_misses", "must be in [0, 1000] (0 = off)");
  executor.Check(c.executor.backoff_m >= 0.0 && c.executor.backoff_m <= 5.0, "backoff_m",
                 "must be in [0, 5]");
  executor.Check(c.executor.no_path_retreat_m >= 0.0 && c.executor.no_path_retreat_m <= 5.0,
                 "no_path_retreat_m", "must be in [0, 5]");
  executor.Check(c.executor.blocked_clearance_step_m >= 0.0, "blocked_clearance_step_m",
                 "must be >= 0");
  executor.Check(
      c.executor.blocked_clearance_max_m >= 0.0 && c.executor.blocked_clearance_max_m <= 2.0,
      "blocked_clearance_max_m", "must be in [0, 2]");
  executor.Check(c.executor.max_blocks_per_goal >= 1, "max_blocks_per_goal", "must be >= 1");
  executor.Check(c.executor.blocked_spot_radius_m >= 0.0, "blocked_spot_radius_m", "must be >= 0");
  executor.Check(c.executor.look_around_after_blocks_at_spot >= 0 &&
                     c.executor.look_around_after_blocks_at_spot <= 100,
                 "look_around_after_blocks_at_spot", "must be in [0, 100] (0 = never)");
  executor.Check(c.executor.max_contacts >= 0 && c.executor.max_contacts <= 32, "max_contacts",
                 "must be in [0, 32] (planning takes at most 32)");
  executor.Check(c.executor.unreachable_region_m >= 0.0 && c.executor.unreachable_region_m <= 20.0,
                 "unreachable_region_m", "must be in [0, 20]");
  executor.Check(c.executor.time_budget_s >= 0.0, "time_budget_s", "must be >= 0 (0 = none)");
  executor.Check(c.executor.endgame_s >= 0.0, "endgame_s", "must be >= 0");
  executor.Check(
      std::isfinite(c.executor.approach_label_match) && c.executor.approach_label_match >= 0.0,
      "approach_label_match", "must be a finite value >= 0 (above 1 = off)");
  executor.Check(std::isfinite(c.executor.min_appearance_agreement) &&
                     c.executor.min_appearance_agreement >= 0.0 &&
                     c.executor.min_appearance_agreement <= 1.0,
                 "min_appearance_agreement", "must be in [0, 1] (0 = off)");
  executor.Check(std::isfinite(c.executor.glance_s) && c.executor.glance_s >= 0.0 &&
                     c.executor.glance_s <= 30.0,
                 "glance_s", "must be in [0, 30] (0 = no glance)");

  ConfigReader memory = section.Child("memory");
  memory.Read("node_spacing_m", &c.memory.node_spacing_m)
      .Read("max_nodes", &c.memory.max_nodes)
      .Read("sectors", &c.memory.sectors);
  memory.Check(c.memory.node_spacing_m > 0.0, "node_spacing_m", "must be > 0");

  if (section.Has("mapping")) {  // absent: no scene graph, the gateway explores
    ConfigReader mapping = section.Child("mapping");
    c.mapping = ClientOptions::FromConfig(mapping, ClientOptions{});
  }

  if (section.Has("planning")) {  // absent: the robot plans locally
    ConfigReader planning = section.Child("planning");
    c.planning.channel = ClientOptions::FromConfig(planning, ClientOptions{});
    std::string strategy(ExplorationStrategyName(c.planning.exploration_strategy));
    planning.Read("exploration_strategy", &strategy)
        .Read("deadline_ms", &c.planning.deadline_ms)
        .Read("goal_tolerance_m", &c.planning.goal_tolerance_m)
        .Read("live_map_max_age_ms", &c.planning.live_map_max_age_ms)
        .Read("clearance_detour_factor", &c.planning.clearance_detour_factor)
        .Read("clearance_detour_m", &c.planning.clearance_detour_m);
    const std::optional<ExplorationStrategy> parsed = ParseExplorationStrategy(strategy);
    planning.Check(parsed.has_value(), "exploration_strategy",
                   "must be NEAREST_FRONTIER, COVERAGE_MAX, SEMANTIC_FRONTIER or EROI_UTILITY");
    if (parsed.has_value()) c.planning.exploration_strategy = *parsed;
    planning.Check(c.planning.deadline_ms > 0, "deadline_ms", "must be > 0");
    planning.Check(c.planning.goal_tolerance_m >= 0.0, "goal_tolerance_m", "must be >= 0");
    planning.Check(c.planning.live_map_max_age_ms >= 0 && c.planning.live_map_max_age_ms <= 10000,
                   "live_map_max_age_ms", "must be in [0, 10000]");
    planning.Check(
        c.planning.clearance_detour_factor == 0.0 || (c.planning.clearance_detour_factor >= 1.0 &&
                                                      c.planning.clearance_detour_factor <= 10.0),
        "clearance_detour_factor", "must be 0 (off) or in [1, 10]");
    planning.Check(c.planning.clearance_detour_m >= 0.0 && c.planning.clearance_detour_m <= 100.0,
                   "clearance_detour_m", "must be in [0, 100]");
  }

  if (section.Has("relocalization")) {  // absent: no relocalization loop
    ConfigReader reloc = section.Child("relocalization");
    c.relocalization.channel = ClientOptions::FromConfig(reloc, ClientOptions{});
    RelocalizationLoopConfig& loop = c.relocalization.loop;
    reloc.Read("map_id", &c.relocalization.map_id)
        .Read("deadline_ms", &c.relocalization.deadline_ms)
        .Read("scan_match_deadline_ms", &c.relocalization.scan_match_deadline_ms)
        .Read("simulated_latency_s", &c.relocalization.simulated_latency_s)
        .Read("jump_distance_m", &loop.jump_distance_m)
        .Read("jump_yaw_rad", &loop.jump_yaw_rad)
        .Read("look_around_rate_rps", &loop.look_around_rate_rps)
        .Read("look_around_duration_s", &loop.look_around_duration_s)
        .Read("query_interval_s", &loop.query_interval_s)
        .Read("answer_timeout_s", &loop.answer_timeout_s)
        .Read("min_observed_objects", &loop.min_observed_objects)
        .Read("max_observed_objects", &loop.max_observed_objects)
        .Read("min_object_detections", &loop.min_object_detections)
        .Read("confirming_answer_m", &loop.confirming_answer_m)
        .Read("confirming_answer_rad", &loop.confirming_answer_rad)
        .Read("max_attempts", &loop.max_attempts)
        .Read("retrigger_after_s", &loop.retrigger_after_s)
        .Read("default_object_scale_m", &loop.default_object_scale_m)
        .Read("refine_with_scan", &loop.refine_with_scan)
        .Read("global_scan_match", &loop.global_scan_match)
        .Read("confirm_min_objects", &loop.confirm_min_objects)
        .Read("confirm_min_cosine", &loop.confirm_min_cosine)
        .Read("confirm_distance_m", &loop.confirm_distance_m)
        .Read("confirm_min_score", &loop.confirm_min_score)
        .Read("confirm_max_ray_conflicts", &loop.confirm_max_ray_conflicts);
    reloc.Check(c.relocalization.map_id.size() <= 128, "map_id", "must be at most 128 characters");
    reloc.Check(c.relocalization.deadline_ms > 0, "deadline_ms", "must be > 0");
    reloc.Check(c.relocalization.scan_match_deadline_ms > 0, "scan_match_deadline_ms",
                "must be > 0");
    reloc.Check(c.relocalization.simulated_latency_s >= 0.0 &&
                    c.relocalization.simulated_latency_s < loop.answer_timeout_s,
                "simulated_latency_s", "must be in [0, answer_timeout_s)");
    reloc.Check(loop.jump_distance_m > 0.0, "jump_distance_m", "must be > 0");
    reloc.Check(loop.jump_yaw_rad > 0.0, "jump_yaw_rad", "must be > 0");
    reloc.Check(loop.look_around_rate_rps > 0.0 && loop.look_around_rate_rps <= 10.0,
                "look_around_rate_rps", "must be in (0, 10]");
    reloc.Check(loop.look_around_duration_s > 0.0, "look_around_duration_s", "must be > 0");
    reloc.Check(loop.query_interval_s >= 0.0 && loop.query_interval_s <= 60.0, "query_interval_s",
                "must be in [0, 60]");
    reloc.Check(loop.answer_timeout_s > 0.0, "answer_timeout_s", "must be > 0");
    reloc.Check(loop.min_observed_objects >= 3, "min_observed_objects",
                "must be >= 3 (a pose needs 3 objects)");
    reloc.Check(
        loop.max_observed_objects >= loop.min_observed_objects && loop.max_observed_objects <= 1000,
        "max_observed_objects", "must be in [min_observed_objects, 1000]");
    reloc.Check(loop.min_object_detections >= 1 && loop.min_object_detections <= 100,
                "min_object_detections", "must be in [1, 100]");
    reloc.Check(loop.confirming_answer_m >= 0.0 && loop.confirming_answer_m <= 10.0,
                "confirming_answer_m", "must be in [0, 10]");
    reloc.Check(loop.confirming_answer_rad >= 0.0 && loop.confirming_answer_rad <= M_PI,
                "confirming_answer_rad", "must be in [0, pi]");
    reloc.Check(loop.max_attempts >= 1, "max_attempts", "must be >= 1");
    reloc.Check(loop.retrigger_after_s >= 0.0, "retrigger_after_s", "must be >= 0");
    reloc.Check(loop.default_object_scale_m > 0.0, "default_object_scale_m", "must be > 0");
    reloc.Check(loop.confirm_min_objects >= 0 && loop.confirm_min_objects <= 100,
                "confirm_min_objects", "must be in [0, 100] (0 = off)");
    reloc.Check(loop.confirm_min_cosine >= -1.0 && loop.confirm_min_cosine <= 1.0,
                "confirm_min_cosine", "must be in [-1, 1]");
    reloc.Check(loop.confirm_distance_m >= 0.0 && loop.confirm_distance_m <= 10.0,
                "confirm_distance_m", "must be in [0, 10]");
    reloc.Check(loop.confirm_min_score >= 0.0 && loop.confirm_min_score <= 1.0, "confirm_min_score",
                "must be in [0, 1]");
    reloc.Check(loop.confirm_max_ray_conflicts >= 0.0 && loop.confirm_max_ray_conflicts <= 1.0,
                "confirm_max_ray_conflicts", "must be in [0, 1]");
  }
  if (section.Has("model_proxy")) {  // absent: offline default, no slow-path calls
    ConfigReader model = section.Child("model_proxy");
    c.model_proxy.channel = ClientOptions::FromConfig(model, ClientOptions{});
    model.Read("model_alias", &c.model_proxy.model_alias)
        .Read("vision_alias", &c.model_proxy.vision_alias)
        .Read("embedding_alias", &c.model_proxy.embedding_alias)
        .Read("deadline_ms", &c.model_proxy.deadline_ms)
        .Read("max_in_flight", &c.model_proxy.max_in_flight)
        .Read("embedding_retry_s", &c.model_proxy.embedding_retry_s)
        .Read("text_embeddings", &c.model_proxy.text_embeddings);
    model.Check(c.model_proxy.deadline_ms > 0, "deadline_ms", "must be > 0");
    model.Check(c.model_proxy.max_in_flight >= 1 && c.model_proxy.max_in_flight <= 16,
                "max_in_flight", "must be in [1, 16]");
    model.Check(c.model_proxy.embedding_retry_s >= 0.0, "embedding_retry_s", "must be >= 0");
    ConfigReader calls = model.Child("calls");
    ModelCallPolicyConfig& p = c.model_proxy.calls;
    calls.Read("new_view_move_m", &p.new_view_move_m)
        .Read("new_view_turn_rad", &p.new_view_turn_rad)
        .Read("new_view_min_new_code_share", &p.new_view_min_new_code_share)
        .Read("backoff_initial_s", &p.backoff_initial_s)
        .Read("backoff_multiplier", &p.backoff_multiplier)
        .Read("backoff_max_s", &p.backoff_max_s)
        .Read("max_calls", &p.max_calls)
        .Read("max_tokens", &p.max_tokens);
    const absl::Status valid = ValidateModelCallPolicy(p);
    calls.Check(valid.ok(), ErrorField(valid).value_or("calls"), valid.message());
  }

  if (section.Has("eroi")) {
    ConfigReader eroi = section.Child("eroi");
    EroiSearchConfig search = DefaultEroiSearch();
    std::vector<double> min{0.0, 0.0, 0.0};
    eroi.Read("min", &min)
        .Read("delta", &search.grid.delta)
        .Read("nx", &search.grid.nx)
        .Read("ny", &search.grid.ny)
        .Read("nz", &search.grid.nz)
        .Read("evidence_radius_m", &search.evidence_radius_m)
        .Read("evidence_once_per_code", &search.evidence_once_per_code)
        .Read("inspect_distance_m", &search.inspect_distance_m)
        .Read("sighting_namings", &search.sighting_namings)
        .Read("failed_clues_to_geometric", &search.failed_clues_to_geometric)
        .Read("region_size", &search.regions.region_size)
        .Read("theta", &search.regions.theta)
        .Read("min_distance_m", &search.mapping.min_distance_m)
        .Read("max_distance_m", &search.mapping.max_distance_m);
    eroi.Check(min.size() == 3, "min", "must be [x, y, z]");
    if (min.size() == 3) search.grid.min = Eigen::Vector3d(min[0], min[1], min[2]);
    eroi.Check(EroiGrid::Create(search.grid).ok(), "delta",
               "grid must have delta > 0, nx, ny, nz >= 0 and at most 26 letters on x and z");
    eroi.Check(search.regions.region_size >= 1, "region_size", "must be >= 1");
    eroi.Check(search.regions.theta >= 1, "theta", "must be >= 1");
    const absl::Status rules = ValidateSearchRules(search);
    eroi.Check(rules.ok(), ErrorField(rules).value_or("eroi"), rules.message());
    c.eroi = search;
  }

  section.Read("default_lease_ttl_s", &c.default_lease_ttl_s)
      .Read("max_lease_ttl_s", &c.max_lease_ttl_s)
      .Read("retained_events", &c.retained_events)
      .Read("keep_finished_tasks", &c.keep_finished_tasks)
      .Read("idempotency_entries", &c.idempotency_entries)
      .Read("state_directory", &c.state_directory)
      .Read("journal_flush_interval_s", &c.journal_flush_interval_s)
      .Read("memory_label_radius_m", &c.memory_label_radius_m)
      .Read("lexicon_path", &c.lexicon_path)
      .Read("prior_path", &c.prior_path);
  section.Check(c.default_lease_ttl_s >= 1.0 && c.default_lease_ttl_s <= c.max_lease_ttl_s,
                "default_lease_ttl_s", "must be in [1, max_lease_ttl_s]");
  section.Check(c.retained_events > 0, "retained_events", "must be > 0");
  section.Check(c.keep_finished_tasks >= 0 && c.keep_finished_tasks <= 100000,
                "keep_finished_tasks", "must be in [0, 100000]");
  section.Check(c.journal_flush_interval_s >= 0.05 && c.journal_flush_interval_s <= 60.0,
                "journal_flush_interval_s", "must be in [0.05, 60]");
  if (absl::Status s = section.Finish(); !s.ok()) return s;
  return c;
}

}  // namespace semnav::reasoning
