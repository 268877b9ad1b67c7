#include "clients/sim/loop/localization_model.h"

#include <cmath>
#include <functional>

namespace semnav::sim::loop {

namespace api = semnav::reasoning::v1;

Pose Compose(const Pose& a, const Pose& b) {
  const double c = std::cos(a.yaw);
  const double s = std::sin(a.yaw);
  Pose out;
  out.position =
      a.position + Eigen::Vector3d(c * b.position.x() - s * b.position.y(),
                                   s * b.position.x() + c * b.position.y(), b.position.z());
  out.yaw = WrapAngle(a.yaw + b.yaw);
  return out;
}

Pose Inverse(const Pose& a) {
  const double c = std::cos(a.yaw);
  const double s = std::sin(a.yaw);
  Pose out;
  out.position = Eigen::Vector3d(-(c * a.position.x() + s * a.position.y()),
                                 -(-s * a.position.x() + c * a.position.y()), -a.position.z());
  out.yaw = WrapAngle(-a.yaw);
  return out;
}

bool IsIdentity(const Pose& a) { return a.position.isZero(0.0) && a.yaw == 0.0; }

Pose FromProto(const semnav::common::v1::Pose& pose) {
  const auto& q = pose.orientation();
  Pose out;
  out.position = Eigen::Vector3d(pose.position().x(), pose.position().y(), pose.position().z());
  out.yaw = std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()),
                       1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
  return out;
}

void ToTruthFrame(api::RobotCommand& command, const Pose& truth_from_odom) {
  if (!command.has_navigate()) return;
  auto move = [&truth_from_odom](semnav::common::v1::Vector3* p) {
    const Pose moved = Compose(truth_from_odom, Pose{Eigen::Vector3d(p->x(), p->y(), p->z()), 0.0});
    p->set_x(moved.position.x());
    p->set_y(moved.position.y());
    p->set_z(moved.position.z());
  };
  api::NavigateAction* navigate = command.mutable_navigate();
  move(navigate->mutable_goal());
  navigate->set_goal_yaw(WrapAngle(navigate->goal_yaw() + truth_from_odom.yaw));
  for (api::PathWaypoint& w : *navigate->mutable_path()) move(w.mutable_position());
}

namespace {

bool Differ(const Pose& a, const Pose& b, const LocalizerConfig& config) {
  return (a.position - b.position).head<2>().norm() > config.lost_distance_m ||
         std::abs(WrapAngle(a.yaw - b.yaw)) > config.lost_yaw_rad;
}

}  // namespace

SimLocalizer::Cell SimLocalizer::CellOf(const Pose& pose) const {
  return {static_cast<int64_t>(std::floor(pose.position.x() / config_.map_cell_m)),
          static_cast<int64_t>(std::floor(pose.position.y() / config_.map_cell_m))};
}

void SimLocalizer::ForSquaresInView(const Pose& believed,
                                    const std::function<void(const Cell&, double)>& visit) const {
  const Cell at = CellOf(believed);
  const auto reach = static_cast<int64_t>(std::ceil(config_.view_m / config_.map_cell_m));
  for (int64_t dx = -reach; dx <= reach; ++dx) {
    for (int64_t dy = -reach; dy <= reach; ++dy) {
      const Cell square{at.first + dx, at.second + dy};
      const Eigen::Vector2d centre((static_cast<double>(square.first) + 0.5) * config_.map_cell_m,
                                   (static_cast<double>(square.second) + 0.5) * config_.map_cell_m);
      const double distance_m = (centre - believed.position.head<2>()).norm();
      if (distance_m <= config_.view_m) visit(square, distance_m);
    }
  }
}

std::optional<Pose> SimLocalizer::Reference(const Pose& believed) const {
  if (config_.reference == LocalizerReference::kTruth) return Pose{};
  std::optional<Pose> nearest;
  double nearest_m = config_.view_m;
  ForSquaresInView(believed, [&](const Cell& square, double distance_m) {
    const auto it = drawn_with_.find(square);
    if (it == drawn_with_.end() || distance_m > nearest_m) return;
    nearest_m = distance_m;
    nearest = it->second;
  });
  return nearest;
}

Pose SimLocalizer::Expected(const Pose& believed, const Pose& truth) const {
  const std::optional<Pose> reference = Reference(believed);
  return reference.has_value() ? Compose(*reference, truth) : truth;
}

api::LocalizationStatus SimLocalizer::Update(double time_s, const Pose& believed, const Pose& truth,
                                             bool mapping) {
  if (!config_.enabled) return api::LOCALIZATION_STATUS_UNSPECIFIED;
  const std::optional<Pose> reference = Reference(believed);
  // Nothing drawn here: the verdict stands.
  const bool mismatch =
      reference.has_value() ? Differ(believed, Compose(*reference, truth), config_) : lost_;
  if (mismatch == lost_) {
    changing_since_.reset();
  } else {
    if (!changing_since_.has_value()) changing_since_ = time_s;
    if (time_s - *changing_since_ >= config_.latency_s) {
      lost_ = mismatch;
      changing_since_.reset();
    }
  }
  if (config_.reference == LocalizerReference::kMap && mapping && !lost_) {
    const Pose believed_from_truth = Compose(believed, Inverse(truth));
    ForSquaresInView(believed, [&](const Cell& square, double) {
      drawn_with_.try_emplace(square, believed_from_truth);
    });
  }
  return lost_ ? api::LOCALIZATION_STATUS_LOST : api::LOCALIZATION_STATUS_OK;
}

void RecoveryTracker::OnKidnap(double time_s) {
  if (open_since_.has_value()) return;
  open_since_ = time_s;
  ++losses_;
}

void RecoveryTracker::OnReport(double time_s, api::LocalizationStatus status) {
  if (status == api::LOCALIZATION_STATUS_LOST && !open_since_.has_value()) {
    open_since_ = time_s;
    ++losses_;
  }
}

void RecoveryTracker::OnCorrection(double time_s, const Pose& believed, const Pose& expected) {
  if (!open_since_.has_value())
    return;  // a correction without a loss (operator request, drift check)
  times_s_.push_back(time_s - *open_since_);
  errors_m_.push_back((believed.position - expected.position).head<2>().norm());
  errors_deg_.push_back(std::abs(WrapAngle(believed.yaw - expected.yaw)) * 180.0 / M_PI);
  open_since_.reset();
}

}  // namespace semnav::sim::loop
