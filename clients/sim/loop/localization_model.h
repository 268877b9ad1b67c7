// The simulated robot's localization (docs/simulation.md, "Losing the pose"): the frame algebra
// between the true pose, the odometry pose and the gateway's map -> odom correction; a simulated
// localizer that notices when what the robot believes departs from the truth; and the per-episode
// recovery figures (losses, recoveries, time to recover, pose error after recovery).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <utility>
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
// a reference and reports LOST once they differ by more than lost_distance_m or lost_yaw_rad for
// latency_s in a row; OK again once they agree for latency_s. Disabled: always OK (UNSPECIFIED
// on the wire, as before the field existed).
//
// The reference (docs/simulation.md, "Losing the pose"):
// - kTruth: the true pose. No real localizer knows it; with odometry drift the map the robot
//   draws drifts too, so a relocalization against that map can never agree with the truth.
// - kMap: the map the robot drew. A localizer matches what it sees against its map around the
//   pose it believes, so it can only notice that the map does not show there what it sees. While
//   the robot maps, every map_cell_m square within view_m of the pose it believes is drawn, once,
//   with the believed-from-true transform of that moment; the model compares the believed pose
//   with the transform of the drawn square nearest it (within view_m) applied to the truth. With
//   no drawn square in view there is no evidence either way. Without drift every square keeps
//   the identity and both references agree.
enum class LocalizerReference { kTruth, kMap };

struct LocalizerConfig {
  bool enabled = false;
  double lost_distance_m = 0.5;
  double lost_yaw_rad = 0.26;  // 15 deg
  double latency_s = 2.0;
  LocalizerReference reference = LocalizerReference::kMap;
  double map_cell_m = 1.0;
  double view_m = 3.0;
};

class SimLocalizer {
 public:
  explicit SimLocalizer(LocalizerConfig config) : config_(config) {}
  // `mapping`: the robot's frames draw the map now (it trusts its pose and is not being
  // relocalized), so the places it stands in are drawn at the believed pose.
  semnav::reasoning::v1::LocalizationStatus Update(double time_s, const Pose& believed,
                                                   const Pose& truth, bool mapping = true);
  // Where a right localizer puts the robot: the reference applied to the truth (the truth itself
  // for kTruth or where nothing was drawn).
  Pose Expected(const Pose& believed, const Pose& truth) const;

 private:
  using Cell = std::pair<int64_t, int64_t>;
  Cell CellOf(const Pose& pose) const;
  // Each square whose centre lies within view_m of the believed pose, with that distance.
  void ForSquaresInView(const Pose& believed,
                        const std::function<void(const Cell&, double)>& visit) const;
  // The believed-from-true transform the map drew the drawn square nearest the believed pose with
  // (kMap; the identity for kTruth; none without a drawn square within view_m).
  std::optional<Pose> Reference(const Pose& believed) const;

  LocalizerConfig config_;
  bool lost_ = false;
  std::optional<double> changing_since_;  // the verdict's opposite has held since then
  std::map<Cell, Pose> drawn_with_;
};

// Per-episode recovery figures. A loss opens at a kidnap, or at the first LOST report while none
// is open; the next correction from the gateway closes it (a recovery) with its time and the
// believed pose's error then, against where a right localizer puts the robot
// (SimLocalizer::Expected).
class RecoveryTracker {
 public:
  void OnKidnap(double time_s);
  void OnReport(double time_s, semnav::reasoning::v1::LocalizationStatus status);
  void OnCorrection(double time_s, const Pose& believed, const Pose& expected);

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
