#include "services/mapping/core/instance_support.h"

#include <algorithm>

namespace semnav::mapping {

InstanceSupport::InstanceSupport(const std::vector<SceneObject>& objects, double margin_m,
                                 double min_share)
    : objects_(objects), margin_m_(margin_m), min_share_(min_share) {}

bool InstanceSupport::operator()(const std::string& label, const Eigen::Vector3f& point) const {
  if (supports_all()) return true;
  if (!built_) {
    for (const SceneObject& object : objects_) {
      const Eigen::Vector3f low =
          (object.position.array() - object.size.array() / 2.0 - margin_m_).matrix().cast<float>();
      const Eigen::Vector3f high =
          (object.position.array() + object.size.array() / 2.0 + margin_m_).matrix().cast<float>();
      // Its own label always (a loaded instance has no votes yet); others with enough of the
      // votes: the detector's rare confusions would otherwise paint every instance, over time,
      // with every label it was once mistaken for.
      boxes_[object.label].emplace_back(low, high);
      double total = 0.0;
      for (const auto& [name, score] : object.label_scores) total += score;
      for (const auto& [name, score] : object.label_scores) {
        if (name != object.label && score >= min_share_ * total)
          boxes_[name].emplace_back(low, high);
      }
    }
    built_ = true;
  }
  const auto it = boxes_.find(label);
  if (it == boxes_.end()) return false;
  return std::any_of(it->second.begin(), it->second.end(), [&](const Box& box) {
    return (point.array() >= box.first.array()).all() &&
           (point.array() <= box.second.array()).all();
  });
}

}  // namespace semnav::mapping
