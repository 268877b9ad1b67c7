// The seed-000 open-space search loop for one task (2.1-2.2, Algorithms 1-2): each camera frame
// gets the visible EROI codes drawn in (inverse mapping) and goes to the VLM with the
// recognition-evaluation-transfer prompt; each `Code: G5A, Description: ...` answer is strong
// evidence for the EROIs within r of the decoded centre (eq. 17-20) and a <position, description>
// record of the region map; every theta = 3 records of a region unit trigger an LLM region score
// (eq. 21-23). The values feed planning's EROI_UTILITY strategy on the same grid. A code whose
// description names the target itself is also kept as a sighting: the robot goes to look
// (sighting_goal.h), since its EROI may hold no unknown cells left to draw the search there.
// Clues the robot reached without finding the target count against the model; after enough of
// them the values stop steering (failed_clues_to_geometric).
#pragma once

#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "services/reasoning/core/eroi_grid.h"
#include "services/reasoning/core/inverse_mapping.h"
#include "services/reasoning/core/region_map.h"
#include "services/reasoning/core/semantic_values.h"

namespace semnav::reasoning {

struct EroiSearchConfig {
  EroiGridSpec grid;               // the search volume (map frame)
  InverseMappingConfig mapping;    // code label window and drawing
  RegionMapConfig regions;         // region units and theta
  double evidence_radius_m = 0.0;  // r of N_r (eq. 18); 0 = one EROI edge (the seed gives no value)
  // A code the VLM names again adds no evidence: overlapping views of one passage are one
  // observation, not independent ones. false = eq. 20 on every answer, as the seed writes.
  bool evidence_once_per_code = true;
  // A code whose description names the target is looked at from this far (sighting_goal.h): within
  // the detector's range (the simulated one's 6 m) with the EROI's cell and an off-by-one code
  // still in view. 0 = sightings are only evidence, as in the seed.
  double inspect_distance_m = 3.0;
  // Answers (of different frames) that must name the target within two EROI edges before the
  // robot goes to look. The model also names the target where it is not (hallucinated clues,
  // confusions) and a look costs a detour of up to the codes' 12 m, but waiting for a second
  // naming lost more than it saved: outdoor mean path 52.3 / 50.4 m with 1, 58.9 / 67.7 m with 2
  // (seeds 1 / 2, docs/performance/mission.md).
  int sighting_namings = 1;
  // ApexNav's switch from semantic to geometric exploration, taken on the model's track record:
  // once the robot has come within r + inspect_distance_m (x-y) of this many clues (codes whose
  // answer raised values) and the search goes on, the model's clues are taken to mislead in this
  // place, and the values stop steering the search (PlanarValues is the prior everywhere;
  // sightings are still looked at). 0 = never, as in the seed.
  int failed_clues_to_geometric = 6;
};

// INVALID_ARGUMENT naming the field: inspect_distance_m outside [0, 50] m, sighting_namings
// outside [1, 10], failed_clues_to_geometric outside [0, 1000].
absl::Status ValidateSearchRules(const EroiSearchConfig& config);

// A camera frame ready for the VLM: the prompt and the codes drawn into the image.
struct EroiObservation {
  std::string prompt;
  std::vector<CodeLabel> labels;  // after occlusion culling (eq. 10)
};

// What a VLM answer changed.
struct EroiEvidence {
  int codes_used = 0;          // pairs whose code decoded inside the grid
  int sightings = 0;           // of them, new codes whose description names the target
  std::vector<RegionDue> due;  // region units now due for an LLM score
};

class EroiSearch {
 public:
  // INVALID_ARGUMENT for a bad grid (see EroiGrid::Create) or an empty target.
  static absl::StatusOr<EroiSearch> Create(std::string target, const EroiSearchConfig& config);

  // Projects and culls the codes for a camera at `position` with orientation `orientation`
  // (body frame x forward, z up; eq. 5-10) and draws them into `image`.
  EroiObservation Annotate(const Eigen::Vector3d& position, const Eigen::Quaterniond& orientation,
                           const PinholeCamera& camera, cv::Mat& image) const;
  // Call economy: how many of the observation's printed codes no frame sent to the VLM printed.
  int NewCodes(const EroiObservation& observation) const;
  // The observation goes to the VLM: its codes are no longer new.
  void OnAsked(const EroiObservation& observation);
  // Applies the VLM's answer (eq. 13 pairs; codes off the grid are skipped).
  EroiEvidence OnVlmAnswer(std::string_view answer);
  // Algorithm 2 step 3a prompt for a due region unit.
  std::string RegionPrompt(const RegionDue& region) const;
  // Eq. 21-23 with the LLM's score; INVALID_ARGUMENT (values unchanged) for an unusable answer.
  absl::Status OnRegionAnswer(const RegionDue& region, std::string_view answer);
  // The robot is at `position` and still searching: clues within r + inspect_distance_m of it
  // (x-y) have failed.
  void OnRobotAt(const Eigen::Vector3d& position);
  // Clues failed so far, and whether the search has turned geometric on them.
  int failed_clues() const { return failed_clues_; }
  bool geometric() const;

  // Values per x-y column (the best over z; the prior everywhere once geometric), row-major with x
  // fastest: the order of planning's eroi_semantic_values over the window PlanningWindow()
  // describes.
  std::vector<double> PlanarValues() const;
  // The map-frame rectangle whose EROIs (edge delta, from its lower-left corner) are this grid's
  // x-y columns: centres at min + delta * (i, j), so the window starts half an edge lower.
  Eigen::Vector2d WindowMin() const;
  Eigen::Vector2d WindowMax() const;

  // Centres of the codes whose description named the target, each once, in the order named.
  const std::vector<Eigen::Vector3d>& sightings() const { return sightings_; }
  double inspect_distance_m() const { return inspect_distance_m_; }
  const EroiGrid& grid() const { return *grid_; }
  const SemanticValues& values() const { return values_; }
  const std::string& target() const { return target_; }

 private:
  EroiSearch(std::string target, EroiGrid grid, const EroiSearchConfig& config);
  // Records a naming of the target at `centre`; true when sighting_namings answers (this one
  // included) named it within two edges.
  bool Corroborated(const Eigen::Vector3d& centre);

  std::string target_;
  std::unique_ptr<const EroiGrid> grid_;  // stable address: the region map refers to it
  double evidence_radius_m_;
  InverseMappingConfig mapping_config_;
  RegionMap regions_;
  SemanticValues values_;
  std::set<std::string> asked_codes_;  // printed into a frame the VLM was asked about
  bool evidence_once_per_code_;
  double inspect_distance_m_;
  int sighting_namings_;
  struct Naming {
    Eigen::Vector3d centre;
    int answer = 0;
  };
  std::vector<Naming> namings_;  // codes answers described as the target (the last 4096)
  int answers_ = 0;
  std::set<std::string> evidenced_codes_;  // named in an answer; kept with evidence_once_per_code
  std::vector<Eigen::Vector3d> sightings_;
  int failed_clues_to_geometric_;
  std::vector<Eigen::Vector2d> open_clues_;  // x-y of evidenced codes the robot has not reached
  int failed_clues_ = 0;
};

}  // namespace semnav::reasoning
