#include "services/reasoning/core/topological_memory.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "services/reasoning/core/fast_resolver.h"

namespace semnav::reasoning {

TopologicalMemory::TopologicalMemory(const LabelMatcher* matcher, TopologicalMemoryConfig config)
    : matcher_(matcher), config_(config) {}

TopoNode* TopologicalMemory::FindNode(int64_t id) {
  for (TopoNode& node : nodes_) {
    if (node.id == id) return &node;
  }
  return nullptr;
}

void TopologicalMemory::Link(int64_t a, int64_t b) {
  TopoNode* na = FindNode(a);
  TopoNode* nb = FindNode(b);
  if (na == nullptr || nb == nullptr || a == b) return;
  if (std::find(na->neighbours.begin(), na->neighbours.end(), b) == na->neighbours.end()) {
    na->neighbours.push_back(b);
    nb->neighbours.push_back(a);
  }
}

int64_t TopologicalMemory::Update(const Eigen::Vector3d& position,
                                  const std::vector<std::string>& labels,
                                  const std::vector<float>& embedding) {
  if (!position.allFinite()) return -1;
  ++clock_;
  TopoNode* nearest = nullptr;
  double best = std::numeric_limits<double>::infinity();
  for (TopoNode& node : nodes_) {
    const double distance = (node.position - position).norm();
    if (distance < best) {
      best = distance;
      nearest = &node;
    }
  }
  int64_t id;
  if (nearest != nullptr && best < config_.node_spacing_m) {
    id = nearest->id;
    if (id != current_) ++nearest->visits;
    for (const std::string& label : labels) {
      if (std::find(nearest->labels.begin(), nearest->labels.end(), label) ==
          nearest->labels.end()) {
        nearest->labels.push_back(label);
      }
    }
    if (!embedding.empty()) nearest->embedding = embedding;
    nearest->last_visit = clock_;
  } else {
    TopoNode node;
    node.id = id = next_id_++;
    node.position = position;
    node.labels = labels;
    node.embedding = embedding;
    node.last_visit = clock_;
    nodes_.push_back(std::move(node));
  }
  if (id != current_) {
    if (current_ >= 0) Link(current_, id);
    previous_ = current_;
    current_ = id;
  }
  if (static_cast<int>(nodes_.size()) > config_.max_nodes) Prune();
  return id;
}

// Oldest, least-visited first: fewest visits, then the earliest id; the current node stays.
void TopologicalMemory::Prune() {
  while (static_cast<int>(nodes_.size()) > config_.max_nodes) {
    auto victim = nodes_.end();
    for (auto it = nodes_.begin(); it != nodes_.end(); ++it) {
      if (it->id == current_) continue;
      if (victim == nodes_.end() || it->visits < victim->visits ||
          (it->visits == victim->visits && it->id < victim->id)) {
        victim = it;
      }
    }
    if (victim == nodes_.end()) return;
    const int64_t gone = victim->id;
    nodes_.erase(victim);
    for (TopoNode& node : nodes_) {
      node.neighbours.erase(std::remove(node.neighbours.begin(), node.neighbours.end(), gone),
                            node.neighbours.end());
    }
    if (previous_ == gone) previous_ = -1;
  }
}

double TopologicalMemory::LabelScore(const PreparedTarget& target, const TopoNode& node) const {
  double best = 0.0;
  for (const std::string& label : node.labels) {
    best = std::max(best, matcher_->Match(target, matcher_->Normalise(label, {})));
  }
  return best;
}

std::optional<MemoryMatch> TopologicalMemory::Query(
    const TargetSpec& target, const std::vector<float>& text_embedding) const {
  std::optional<MemoryMatch> best;
  const PreparedTarget prepared = matcher_->Prepare(target);
  for (const TopoNode& node : nodes_) {
    double score = LabelScore(prepared, node);
    if (!text_embedding.empty() && node.embedding.size() == text_embedding.size()) {
      score = 0.5 * score + 0.5 * std::max(0.0, Cosine(text_embedding, node.embedding));
    }
    if (score > 0.0 && (!best.has_value() || score > best->score))
      best = MemoryMatch{node.id, node.position, score};
  }
  return best;
}

double TopologicalMemory::LeastExploredYaw(const Eigen::Vector3d& position) const {
  const int sectors = std::max(1, config_.sectors);
  const double width = 2.0 * M_PI / sectors;
  std::vector<int> visits(static_cast<std::size_t>(sectors), 0);
  for (const TopoNode& node : nodes_) {
    const Eigen::Vector3d offset = node.position - position;
    // A NaN angle would index outside the sectors (the gateway crashed on a NaN pose).
    if (!offset.allFinite() || offset.head<2>().norm() < 1e-6) continue;
    double angle = std::atan2(offset.y(), offset.x()) + width / 2.0;
    angle = std::fmod(angle + 2.0 * M_PI, 2.0 * M_PI);
    const int sector = std::min(sectors - 1, static_cast<int>(angle / width));
    visits[static_cast<std::size_t>(sector)] += node.visits;
  }
  const auto least = std::min_element(visits.begin(), visits.end());
  const double yaw = width * static_cast<double>(least - visits.begin());
  return yaw > M_PI ? yaw - 2.0 * M_PI : yaw;
}

std::optional<Eigen::Vector3d> TopologicalMemory::BacktrackPosition(
    const TargetSpec& target) const {
  const TopoNode* seen = nullptr;
  const PreparedTarget prepared = matcher_->Prepare(target);
  for (const TopoNode& node : nodes_) {
    if (!target.empty() && LabelScore(prepared, node) > 0.0 &&
        (seen == nullptr || node.last_visit > seen->last_visit)) {
      seen = &node;
    }
  }
  if (seen != nullptr) return seen->position;
  for (const TopoNode& node : nodes_) {
    if (node.id == previous_) return node.position;
  }
  return std::nullopt;
}

}  // namespace semnav::reasoning
