// Topological memory (seed 002, 3.2.3): a node every 2 m with the labels (and embedding) visible
// there; text query; the least-explored of 8 sectors; backtrack to where a target was last seen;
// pruning of the oldest, least-visited nodes past 500.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "services/reasoning/core/label_matcher.h"

namespace semnav::reasoning {

struct TopologicalMemoryConfig {
  double node_spacing_m = 2.0;  // a new node once the robot is this far from every node.
  int max_nodes = 500;          // prune beyond this many.
  int sectors = 8;              // least-explored direction resolution.
};

struct TopoNode {
  int64_t id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::vector<std::string> labels;  // object labels visible from here (union over visits).
  std::vector<float> embedding;     // image embedding of the latest visit; may be empty.
  int visits = 1;
  uint64_t last_visit = 0;          // update counter of the latest visit.
  std::vector<int64_t> neighbours;  // nodes visited directly before or after this one.
};

struct MemoryMatch {
  int64_t node_id = 0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double score = 0.0;
};

class TopologicalMemory {
 public:
  // `matcher` must outlive the memory.
  TopologicalMemory(const LabelMatcher* matcher, TopologicalMemoryConfig config);

  // Records the robot at `position` seeing `labels`: revisits the nearest node if it is closer
  // than the spacing, else creates a node linked to the previous one. Returns the current node id
  // (-1, nothing recorded, for a non-finite position: a NaN node would poison every query).
  int64_t Update(const Eigen::Vector3d& position, const std::vector<std::string>& labels,
                 const std::vector<float>& embedding);

  // Best node for a text target: label match over its labels, averaged with max(0, cosine) when
  // both embeddings exist. nullopt when nothing matches.
  std::optional<MemoryMatch> Query(const TargetSpec& target,
                                   const std::vector<float>& text_embedding) const;
  // Yaw (rad, 0 = +x, counter-clockwise) of the centre of the sector around `position` holding the
  // fewest node visits; ties go to the lowest sector index.
  double LeastExploredYaw(const Eigen::Vector3d& position) const;
  // Position of the most recent visit of a node that saw `target`, else of the node visited before
  // the current one (LOVON backtrack); nullopt if neither exists.
  std::optional<Eigen::Vector3d> BacktrackPosition(const TargetSpec& target) const;

  const std::vector<TopoNode>& nodes() const { return nodes_; }
  int64_t current() const { return current_; }

 private:
  TopoNode* FindNode(int64_t id);
  void Link(int64_t a, int64_t b);
  void Prune();
  double LabelScore(const PreparedTarget& target, const TopoNode& node) const;

  const LabelMatcher* matcher_;
  TopologicalMemoryConfig config_;
  std::vector<TopoNode> nodes_;
  int64_t next_id_ = 1;
  int64_t current_ = -1;
  int64_t previous_ = -1;
  uint64_t clock_ = 0;
};

}  // namespace semnav::reasoning
