// The simulated robot's localization (docs/simulation.md, "Losing the pose"): the frame algebra
// between the true pose, the odometry pose and the gateway's map -> odom correction; a simulated
// localizer that notices when what the robot believes departs from the truth; and the per-episode
// recovery figures (losses, recoveries, time to recover, pose error after recovery).
#pragma once

#include <optional>
#include <vector>

#include "clients/sim/core/odometry.h"
#include "semnav/reasoning/v1/robot_session.pb.h"

namespace semnav::sim::loop {

// Planar rigid transforms as poses: Compose(a, b) = a * b, Inverse(a) * a = identity.
Pose Compose(const Pose& a, const Pose& b);
Pose Inverse(const Pose& a);
bool IsIdentity(const Pose& a);
Pose FromProto(const semnav::common::v1::Pose& pose);
// A navigate command's goal, heading and path from the robot's odometry frame into the world:
// the simulator drives true poses, the robot steers by its odometry.
void ToTruthFrame(semnav::reasoning::v1::RobotCommand& command, const Pose& truth_from_odom);

// The localizer's model: it compares the pose the robot believes (map_from_odom * odometry) with
// the truth and reports LOST once they differ by more than lost_distance_m or lost_yaw_rad for
// latency_s in a row; OK again once they agree for latency_s. Disabled: always OK (UNSPECIFIED
// on the wire, as before the field existed).
struct LocalizerConfig {
  bool enabled = false;
  double lost_distance_m = 0.5;
  double lost_yaw_rad = 0.26;  // 15 deg
  double latency_s = 2.0;
};

class SimLocalizer {
 public:
  explicit SimLocalizer(LocalizerConfig config) : config_(config) {}
  semnav::reasoning::v1::LocalizationStatus Update(double time_s, const Pose& believed,
                                                   const Pose& truth);

 private:
  LocalizerConfig config_;
  bool lost_ = false;
  std::optional<double> changing_since_;  // the verdict's opposite has held since then
};

// Per-episode recovery figures. A loss opens at a kidnap, or at the first LOST report while none
// is open; the next correction from the gateway closes it (a recovery) with its time and the
// believed pose's error then.
class RecoveryTracker {
 public:
  void OnKidnap(double time_s);
  void OnReport(double time_s, semnav::reasoning::v1::LocalizationStatus status);
  void OnCorrection(double time_s, const Pose& believed, const Pose& truth);

  int losses() const { return losses_; }
  int recoveries() const { return static_cast<int>(times_s_.size()); }
  const std::vector<double>& times_s() const { return times_s_; }
  const std::vector<double>& errors_m() const { return errors_m_; }
  const std::vector<double>& errors_deg() const { return errors_deg_; }

 private:
  std::optional<double> open_since_;
  int losses_ = 0;
  std::vector<double> times_s_, errors_m_, errors_deg_;
};

}  // namespace semnav::sim::loop
