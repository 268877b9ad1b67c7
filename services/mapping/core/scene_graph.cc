#include "services/mapping/core/scene_graph.h"

#include <algorithm>
#include <cmath>

#include "services/mapping/core/scene_relations.h"

namespace semnav::mapping {
namespace {

void Normalize(std::vector<float>& v) {
  double norm = 0.0;
  for (float x : v) norm += static_cast<double>(x) * x;
  norm = std::sqrt(norm);
  if (norm == 0.0) return;
  for (float& x : v) x = static_cast<float>(x / norm);
}

}  // namespace

double Cosine(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.empty() || a.size() != b.size()) return 0.0;
  double dot = 0.0;
  double na = 0.0;
  double nb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    dot += static_cast<double>(a[i]) * b[i];
    na += static_cast<double>(a[i]) * a[i];
    nb += static_cast<double>(b[i]) * b[i];
  }
  return na == 0.0 || nb == 0.0 ? 0.0 : dot / std::sqrt(na * nb);
}

SceneObject* SceneGraph::Match(const ObjectObservation& observation) {
  // A view from a pose the robot does not trust is in an unknown frame: merged into a trusted
  // instance it would drag that instance toward the wrong place and hide the view from
  // relocalization, which needs what the robot sees in its own frame. A trusted view prefers the
  // trusted instances, and joins one found while the robot was lost only when none matches.
  if (observation.pose_untrusted) return MatchAmong(observation, /*untrusted=*/true);
  SceneObject* trusted = MatchAmong(observation, /*untrusted=*/false);
  return trusted != nullptr ? trusted : MatchAmong(observation, /*untrusted=*/true);
}

SceneObject* SceneGraph::MatchAmong(const ObjectObservation& observation, bool untrusted) {
  SceneObject* best = nullptr;
  if (!observation.embedding.empty()) {
    double best_cosine = config_.embedding_min_cosine;
    for (SceneObject& o : objects_) {
      if (o.pose_untrusted != untrusted) continue;
      if ((o.position - observation.position).norm() > config_.embedding_max_distance_m) continue;
      const double c = Cosine(o.embedding, observation.embedding);
      if (c >= best_cosine) {
        best_cosine = c;
        best = &o;
      }
    }
    if (best != nullptr) return best;
  }
  // Fallback for instances the embedding cannot judge (either side has none).
  double best_distance = config_.label_max_distance_m;
  for (SceneObject& o : objects_) {
    if (o.pose_untrusted != untrusted) continue;
    if (o.label != observation.label) continue;
    if (!observation.embedding.empty() && o.embedding.size() == observation.embedding.size())
      continue;
    const double d = (o.position - observation.position).norm();
    if (d <= best_distance) {
      best_distance = d;
      best = &o;
    }
  }
  return best;
}

void SceneGraph::Merge(SceneObject& object, const ObjectObservation& observation) {
  const double w = config_.ema_new_weight;
  object.position = w * observation.position + (1.0 - w) * object.position;
  object.size = w * observation.size + (1.0 - w) * object.size;
  if (!observation.embedding.empty()) {
    std::vector<float> incoming = observation.embedding;
    Normalize(incoming);
    if (object.embedding.size() != incoming.size()) {
      object.embedding = incoming;
    } else {
      for (size_t i = 0; i < incoming.size(); ++i) {
        object.embedding[i] = static_cast<float>(w * incoming[i] + (1.0 - w) * object.embedding[i]);
      }
      Normalize(object.embedding);
    }
  }
  // An instance loaded from a map file has no votes yet: its label stands for all its detections.
  if (object.label_scores.empty())
    object.label_scores[object.label] = object.score * object.detection_count;
  object.label_scores[observation.label] += observation.score;
  const auto best =
      std::max_element(object.label_scores.begin(), object.label_scores.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  if (best->second > object.label_scores.at(object.label))
    object.label = best->first;  // ties keep it
  object.score =
      (object.score * object.detection_count + observation.score) / (object.detection_count + 1);
  ++object.detection_count;
  object.pose_untrusted = object.pose_untrusted || observation.pose_untrusted;
  object.last_seen_ns = std::max(object.last_seen_ns, observation.stamp_ns);
  object.revision = revision_ + 1;
}

void SceneGraph::MarkPoseUntrustedSince(int64_t since_ns) {
  for (SceneObject& object : objects_) {
    if (object.last_seen_ns >= since_ns) object.pose_untrusted = true;
  }
}

std::vector<SceneObject> SceneGraph::Integrate(const std::vector<ObjectObservation>& observations,
                                               int64_t now_ns) {
  return Integrate(observations, now_ns, [](const SceneObject&) { return false; });
}

std::vector<SceneObject> SceneGraph::Integrate(
    const std::vector<ObjectObservation>& observations, int64_t now_ns,
    absl::FunctionRef<bool(const SceneObject&)> expected_in_view) {
  bool changed = false;
  std::vector<uint64_t> matched;
  for (const ObjectObservation& observation : observations) {
    SceneObject* object = Match(observation);
    matched.push_back(object != nullptr ? object->id : next_id_);
    if (object == nullptr) {
      SceneObject fresh;
      fresh.id = next_id_++;
      fresh.label = observation.label;
      fresh.label_scores[observation.label] = observation.score;
      fresh.position = observation.position;
      fresh.size = observation.size;
      fresh.embedding = observation.embedding;
      Normalize(fresh.embedding);
      fresh.score = observation.score;
      fresh.detection_count = 1;
      fresh.first_seen_ns = fresh.last_seen_ns = observation.stamp_ns;
      fresh.pose_untrusted = observation.pose_untrusted;
      fresh.revision = revision_ + 1;
      objects_.push_back(std::move(fresh));
    } else {
      Merge(*object, observation);
    }
    changed = true;
  }
  const ExistenceConfig& existence = config_.existence;
  if (existence.enabled) {
    for (SceneObject& o : objects_) {
      if (std::find(matched.begin(), matched.end(), o.id) != matched.end()) continue;
      if (!expected_in_view(o)) continue;
      ++o.misses;
      // Watchers get the count with the next revision; a miss alone does not make one, so the
      // revisions (and what clients do per revision) stay those of the detections.
      o.revision = revision_ + 1;
    }
  }
  const auto prune_ns = static_cast<int64_t>(config_.prune_single_after_s * 1e9);
  const auto stale = [&](const SceneObject& o) {
    if (existence.enabled && o.misses >= existence.min_misses &&
        o.misses > existence.max_misses_per_detection * o.detection_count) {
      return true;
    }
    return o.detection_count == 1 && now_ns - o.last_seen_ns > prune_ns;
  };
  std::vector<SceneObject> removed;
  for (const SceneObject& o : objects_) {
    if (!stale(o)) continue;
    removals_.push_back({revision_ + 1, o.id});
    removed.push_back(o);
  }
  objects_.erase(std::remove_if(objects_.begin(), objects_.end(), stale), objects_.end());
  changed = changed || !removed.empty();
  if (removals_.size() > config_.removal_log_size) {
    const size_t drop = removals_.size() - config_.removal_log_size;
    forgotten_before_ = removals_[drop - 1].first;
    removals_.erase(removals_.begin(), removals_.begin() + static_cast<std::ptrdiff_t>(drop));
  }
  if (!changed) return removed;
  ++revision_;
  Rebuild();
  return removed;
}

void SceneGraph::Rebuild() {
  std::vector<int> region_before;
  region_before.reserve(objects_.size());
  for (const SceneObject& o : objects_) region_before.push_back(o.region_id);
  relations_ = ComputeRelations(objects_, config_.relations);
  regions_ = ComputeRegions(objects_, config_.relations);
  // Region ids follow the lowest member id, so a removal or a merge renumbers the regions of
  // instances that did not change themselves. They ride along with this revision's delta: a
  // watcher's mirror kept their old ids, disagreeing with the regions it was sent, and the
  // gateway's graph then depended on whether a watch delta or a full fetch brought a revision.
  for (size_t i = 0; i < objects_.size(); ++i) {
    if (objects_[i].region_id != region_before[i]) objects_[i].revision = revision_;
  }
}

std::string SceneGraph::Summary() const { return Summarize(objects_, regions_); }

const SceneObject* SceneGraph::Find(uint64_t id) const {
  for (const SceneObject& o : objects_) {
    if (o.id == id) return &o;
  }
  return nullptr;
}

std::optional<SceneDelta> SceneGraph::ChangesSince(uint64_t since) const {
  if (since < forgotten_before_) return std::nullopt;
  SceneDelta delta;
  for (const SceneObject& o : objects_) {
    if (o.revision > since) delta.upserted_ids.push_back(o.id);
  }
  for (const auto& [revision, id] : removals_) {
    if (revision > since) delta.removed_ids.push_back(id);
  }
  return delta;
}

void SceneGraph::Replace(std::vector<SceneObject> objects, uint64_t next_id) {
  for (const SceneObject& o : objects_) removals_.push_back({revision_ + 1, o.id});
  ++revision_;
  objects_ = std::move(objects);
  for (SceneObject& o : objects_) o.revision = revision_;
  next_id_ = next_id;
  Rebuild();
}

}  // namespace semnav::mapping
