// Settings of semnav-gateway (YAML section "gateway"); every default is the seed's value.
#pragma once

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "services/common/client/channel.h"
#include "services/common/config/config_reader.h"
#include "services/reasoning/core/eroi_search.h"
#include "services/reasoning/core/exploration_strategy.h"
#include "services/reasoning/core/fast_resolver.h"
#include "services/reasoning/core/model_call_policy.h"
#include "services/reasoning/core/relocalization_loop.h"
#include "services/reasoning/core/slow_answer.h"
#include "services/reasoning/core/task_decomposer.h"
#include "services/reasoning/core/task_executor.h"
#include "services/reasoning/core/task_registry.h"
#include "services/reasoning/core/topological_memory.h"

namespace semnav::reasoning {

// The planning service (section "planning"). No address = no planning: the robot plans every
// path locally and exploration steps toward the topological memory's least-explored sector.
struct PlanningSettings {
  ClientOptions channel;  // address empty = no planning service
  ExplorationStrategy exploration_strategy = ExplorationStrategy::kSemanticFrontier;
  int deadline_ms = 2000;  // per PlanPath / SelectExplorationGoal
  double goal_tolerance_m =
      0.0;  // an occupied goal may move this far; 0 = use the alternative point
  // Wall-clock sessions accept a live grid planning fetched this long ago (LiveMapGrid.max_age_ms),
  // as Nav2's planners read a global costmap updated at 1 Hz: one fetch then serves the calls
  // of many robots. Simulated-clock sessions always ask for a fresh grid. 0 = always fresh.
  int live_map_max_age_ms = 500;
  // A path planned with the executor's clearance that is longer than the straight line by this
  // factor and these metres is also planned with the bare footprint, and the bare way is taken
  // when the clearance's is longer than it by as much: a gap narrower than footprint plus
  // clearance on the short way sent a robot 16 m the wrong way through space it had not seen
  // (FR-079 start 1, docs/performance/mission.md). factor 0 = always the clearance's way.
  double clearance_detour_factor = 1.5;
  double clearance_detour_m = 3.0;
};

// The model proxy (section "model_proxy"). No address = offline default: fast path, the commonsense
// prior for exploration and plain exploration; no slow-path calls.
struct ModelSettings {
  ClientOptions channel;     // address empty = no model proxy (127.0.0.1:50054 in the local stack)
  std::string model_alias;   // Complete alias; "" = the proxy's default
  std::string vision_alias;  // Complete alias for image prompts (a VLM chain); "" = the default
  std::string embedding_alias;    // Embed alias; "" = the proxy's default
  int deadline_ms = 5000;         // per call including the proxy's fallbacks (seed 000 Table 3:
                                  // VLM 1.51 s, LLM 0.35 s mean)
  int max_in_flight = 2;          // concurrent calls (worker threads)
  double embedding_retry_s = 60;  // after Embed is unavailable, answer that locally this long
  bool text_embeddings = true;    // ask Embed for each task's target text
  ModelCallPolicyConfig calls;    // per-task call economy (section model_proxy.calls)
};

// The relocalization service and the gateway's relocalization loop (section "relocalization";
// docs/algorithms/relocalization.md, "The loop"). No address = no loop: robot reports and pose
// jumps are ignored and RelocalizeRobot is FAILED_PRECONDITION, as before the loop existed.
struct RelocalizationSettings {
  ClientOptions channel;   // address empty = no relocalization service
  std::string map_id;      // landmark map robots relocalize in; "" = the robot's id
  int deadline_ms = 2000;  // per Relocalize call (wall clock)
  // Per MatchLostScan call to mapping (wall clock): a global match over a 50 x 50 m map takes
  // ~1 s of one core, more on a loaded machine.
  int scan_match_deadline_ms = 10000;
  // Simulated-clock robots get the answer this many simulated seconds after the call (the
  // service's median is ~5 ms; the rest is the robot's link), so episodes replay exactly.
  double simulated_latency_s = 0.5;
  RelocalizationLoopConfig loop;
};

// The EROI search a volume starts from: 2 m edges, planning's default eroi_size_m (the seed's
// example uses 3 m), everything else as EroiSearchConfig has it.
EroiSearchConfig DefaultEroiSearch();

struct GatewayConfig {
  DecomposerConfig decomposer;
  FastResolverConfig fast_path;
  SlowPathConfig slow_path;
  ExecutorConfig executor;
  TopologicalMemoryConfig memory;
  double default_lease_ttl_s = 30.0;  // AcquireLease without ttl
  double max_lease_ttl_s = 600.0;     // longest lease
  int retained_events = 10000;        // event log replay window
  // Finished tasks GetTask/ListTasks still answer for; older ones are forgotten (NOT_FOUND).
  // 256 is about 5 minutes of a 50-robot fleet (the fleet soak), ~15 KiB each.
  int keep_finished_tasks = static_cast<int>(TaskRegistry::kDefaultKeepFinished);
  int idempotency_entries = 4096;  // remembered request_ids
  // Where tasks, leases and events survive a gateway crash (GatewayJournal); "" = kept in memory
  // only. A running task comes back PAUSED and resumes with its robot's next state.
  std::string state_directory;
  double journal_flush_interval_s = 1.0;  // the most a crash can lose
  std::string lexicon_path =
      Lexicon::DefaultPath();  // bilingual lexicon (TSV); default: the source tree's
  ClientOptions mapping;       // mapping service; empty address = no scene graph
  PlanningSettings planning;
  RelocalizationSettings relocalization;
  ModelSettings model_proxy;
  // Seed-000 search volume for EROI_UTILITY tasks (section "eroi"); a task's search area replaces
  // its x / y extent. Absent and no search area = those tasks explore with planning's uniform
  // values. `eroi.delta` must equal planning's exploration.eroi_size_m.
  std::optional<EroiSearchConfig> eroi;
  // ConceptNet AtLocation prior (co-occurrence for SEMANTIC_FRONTIER); "" = no prior. Default:
  // the shared data folder beside the checkout, as the model proxy reads it.
  std::string prior_path = DefaultPriorPath();
  double memory_label_radius_m = 3.0;  // scene-graph objects this close count as seen at a memory
                                       // node (no per-frame visibility reaches the gateway)

  static std::string DefaultPriorPath();
  // The settings of `section`; a bad value, a failed check or an unknown key fails with its
  // key path (bad values are also recorded on `section`).
  static absl::StatusOr<GatewayConfig> FromYaml(ConfigReader& section);
};

}  // namespace semnav::reasoning
