#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/functional/function_ref.h"
#include "services/mapping/core/scene_types.h"

namespace semnav::mapping {

// Negative evidence, existence tracking as in Fusion++ (McCormac et al. 2018) and Khronos: a frame
// in which the camera should have detected an instance (ExpectedInView) but did not counts a miss
// against it. Instances missed far more often than detected are dropped. Without it, every false
// detection that recurred once stayed for good: a 50-robot fleet's home of 18 objects grew to 80
// instances in 3 minutes (docs/performance.md, "Fleet").
struct ExistenceConfig {
  bool enabled = true;
  // When an instance counts as expected in view. Conservative on purpose: an instance the
  // detector could not have seen must never lose existence, so the range is below a typical
  // detector's and the apparent size well above the smallest it reports.
  double max_range_m = 4.0;            // centre depth along the optical axis
  double min_view_fraction = 0.002;    // projected extent / image area (600 px of 640 x 480)
  double image_margin = 0.1;           // of width and height: the centre well inside the image
  double occlusion_tolerance_m = 0.3;  // depth at the centre may be this much nearer than the front
  // Dropped once misses >= min_misses and misses > max_misses_per_detection x detections.
  int min_misses = 8;
  double max_misses_per_detection = 3.0;
};

struct SceneGraphConfig {
  double ema_new_weight = 0.3;            // seed 002: new = 0.3 * detection + 0.7 * existing
  double embedding_min_cosine = 0.8;      // embedding match needs at least this cosine
  double embedding_max_distance_m = 3.0;  // ... and the instance within this distance
  double label_max_distance_m = 1.0;      // fallback match: same label within this distance
  double prune_single_after_s = 10.0;     // drop instances seen once and not again for this long
  // When a robot's frames turn untrusted, instances seen this long before its first untrusted
  // frame are marked too: a localizer reports a lost pose late (the simulator's model after 2 s
  // of disagreement, on the next 0.5 s step: 2.5 s; set it to the robot localizer's latency).
  double untrusted_lookback_s = 2.5;
  size_t removal_log_size = 4096;  // removals remembered for resumable watches
  ExistenceConfig existence;
  RelationConfig relations;
};

// What changed after a revision, for resumable watches.
struct SceneDelta {
  std::vector<uint64_t> upserted_ids;
  std::vector<uint64_t> removed_ids;
};

// Instance tracking and scene graph of seed 002 (ConceptGraphs / SG-Nav style).
class SceneGraph {
 public:
  explicit SceneGraph(const SceneGraphConfig& config) : config_(config) {}

  // Matches each observation to an instance embedding-first (best cosine >= embedding_min_cosine
  // within embedding_max_distance_m), else by same label nearest within label_max_distance_m among
  // instances the embedding cannot judge (one side has none: two differing embeddings never merge).
  // A view with pose_untrusted matches only untrusted instances; a trusted view trusted ones
  // first. Merges with EMA (position, size, embedding), counts detections and averages scores; new
  // instances otherwise. Then prunes stale single detections (relative to `now_ns`) and rebuilds
  // relations and regions. Bumps the revision when anything changed.
  // Both overloads return the instances they removed.
  std::vector<SceneObject> Integrate(const std::vector<ObjectObservation>& observations,
                                     int64_t now_ns);
  // The same for one camera frame: every instance that matched none of its observations but
  // `expected_in_view` says the frame should have shown counts a miss, and instances missed
  // beyond ExistenceConfig's bound are removed.
  std::vector<SceneObject> Integrate(const std::vector<ObjectObservation>& observations,
                                     int64_t now_ns,
                                     absl::FunctionRef<bool(const SceneObject&)> expected_in_view);

  uint64_t revision() const { return revision_; }
  const std::vector<SceneObject>& objects() const { return objects_; }
  const std::vector<Relation>& relations() const { return relations_; }
  const std::vector<Region>& regions() const { return regions_; }
  std::string Summary() const;
  const SceneObject* Find(uint64_t id) const;
  // Changes after `since`; nullopt when removals that old were forgotten (send a snapshot).
  std::optional<SceneDelta> ChangesSince(uint64_t since) const;
  // Marks every instance last seen at or after `since_ns` as pose_untrusted (the frames of a
  // robot's loss before it reported it). Does not bump the revision: nothing a watcher sees
  // changed.
  void MarkPoseUntrustedSince(int64_t since_ns);
  // Replaces the whole graph (map load / reset); bumps the revision.
  void Replace(std::vector<SceneObject> objects, uint64_t next_id);
  uint64_t next_id() const { return next_id_; }

 private:
  SceneObject* Match(const ObjectObservation& observation);
  // Match among the instances whose pose_untrusted equals `untrusted`.
  SceneObject* MatchAmong(const ObjectObservation& observation, bool untrusted);
  void Merge(SceneObject& object, const ObjectObservation& observation);
  void Rebuild();

  SceneGraphConfig config_;
  std::vector<SceneObject> objects_;
  std::vector<Relation> relations_;
  std::vector<Region> regions_;
  std::vector<std::pair<uint64_t, uint64_t>> removals_;  // (revision, id), oldest first
  uint64_t forgotten_before_ = 0;  // removals at or below this revision are gone
  uint64_t revision_ = 0;
  uint64_t next_id_ = 1;
};

// Cosine similarity; 0 when either vector is empty, zero or of a different length.
double Cosine(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace semnav::mapping
