#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "services/mapping/core/scene_types.h"

namespace semnav::mapping {

// Which labelled points the scene graph still holds (SemanticMapConfig::instance_support_*): a
// point is supported when an instance named by its label, or whose votes give that label at least
// min_share of their summed score, holds it within its fused box (position +- size / 2, what the
// scene graph publishes) grown by the margin. A negative margin supports every point.
class InstanceSupport {
 public:
  InstanceSupport(const std::vector<SceneObject>& objects, double margin_m, double min_share);

  bool operator()(const std::string& label, const Eigen::Vector3f& point) const;
  bool supports_all() const { return margin_m_ < 0.0; }

 private:
  using Box = std::pair<Eigen::Vector3f, Eigen::Vector3f>;  // min, max corners
  const std::vector<SceneObject>& objects_;
  double margin_m_;
  double min_share_;
  // Per label, built at the first question: most frames ask none (no prune due, no removal).
  mutable bool built_ = false;
  mutable std::map<std::string, std::vector<Box>> boxes_;
};

}  // namespace semnav::mapping
