// Two robots, one frame (issue 16, item 4): robot A surveys a generated home and saves its map;
// robot B starts in the same home at an unknown rigid offset (its odometry frame is the world
// turned and shifted), looks around (again a few metres on while the alignment is not
// reliable), is aligned to A's map by the relocalization service's AlignMaps, and goes straight
// to an object A saw, without exploring. B's moves run on the ground-truth grid, standing in for
// its local planner; they are path lengths, not driven. Everything
// travels over the real services (TwoRobotEndpoints); the world and all choices are a function
// of the options.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "clients/sim/loop/two_robot_stack.h"

namespace semnav::sim::loop {

struct TwoRobotOptions {
  uint64_t world_seed = 1;        // the generated home
  int trials = 5;                 // robot B runs in this home
  uint64_t trial_seed = 1;        // B's starts, offsets and targets
  double success_radius_m = 1.0;  // B succeeds stopping this close to the target's footprint
  // B aims this much inside the success radius, to absorb the alignment error.
  double approach_margin_m = 0.25;
  // On its way B stops where its camera sees the target within the success radius less this
  // (the gateway executor's success_margin_m: success in view); what it sees needs no alignment.
  double sight_margin_m = 0.2;
  double look_step_deg = 10.0;    // heading step of B's look-arounds
  double survey_step_deg = 10.0;  // heading step of A's look-around in every room
  double max_offset_m = 30.0;     // B's unknown offset: translation up to this, any heading
  // Look-arounds B may take before giving up on a reliable alignment; between two, B moves to
  // the nearest place (by path) at least move_m from every place it looked from.
  int max_look_arounds = 5;
  double move_m = 3.0;
  // B's look-around depth also goes to A's mapping as a lost robot's (pose_untrusted), and
  // MatchLostScan refines a reliable object alignment against A's grid, or, without one, matches
  // it globally (docs/algorithms/relocalization.md, section 8). Off: objects alone, as before.
  bool scan_match = true;
};

// TwoRobotTrial::alignment.
inline constexpr char kAlignedByObjects[] = "objects";
inline constexpr char kAlignedByObjectsScanRefined[] = "objects, scan-refined";
inline constexpr char kAlignedByGlobalScanMatch[] = "global scan match";

struct TwoRobotTrial {
  int index = 0;
  std::string target_id;  // world object id of the target (ground truth)
  std::string target_label;
  int b_landmarks = 0;    // landmarks in B's map after its last look-around
  int look_arounds = 0;   // look-arounds B took (the first where it starts)
  bool aligned = false;   // AlignMaps answered
  bool reliable = false;  // ... with a reliable pose (B moves only then)
  // What gave the pose B moved on: one of the kAlignedBy... names below, "" when none did.
  std::string alignment;
  int inliers = 0;
  double rms_residual_m = 0.0;       // of the inliers, metres
  double align_ms = 0.0;             // AlignMaps round trip
  double alignment_error_m = 0.0;    // |estimated - true| position of B's start in A's frame
  double alignment_error_deg = 0.0;  // heading error of the estimated transform
  double path_m = 0.0;               // B's route: start to its believed goal region
  double shortest_m = 0.0;  // geodesic from B's start to the true success region of the target
  double path_ratio = 0.0;  // path_m / shortest_m
  double look_m = 0.0;      // part of path_m spent moving between look-arounds
  // The route after the reliable alignment against the geodesic from where B was aligned: how
  // straight B goes once it trusts its pose.
  double route_ratio = 0.0;
  double distance_to_target_m = 0.0;  // from where B stops to the target's footprint
  bool success = false;
  std::string failure;  // why not, empty on success
};

struct TwoRobotWorldResult {
  std::string world;
  int a_viewpoints = 0;
  int a_frames = 0;
  int a_landmarks = 0;  // in A's saved map
  std::vector<TwoRobotTrial> trials;
};

// INVALID_ARGUMENT for options out of range; service errors pass through (a failed alignment
// is a trial result, not an error).
absl::StatusOr<TwoRobotWorldResult> RunTwoRobotWorld(const TwoRobotOptions& options,
                                                     const TwoRobotEndpoints& endpoints);

}  // namespace semnav::sim::loop
