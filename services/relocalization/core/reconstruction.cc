#include "services/relocalization/core/reconstruction.h"

#include <algorithm>
#include <cmath>

#include "services/common/status/field_error.h"
#include "services/relocalization/core/hungarian.h"

namespace semnav::relocalization {

absl::StatusOr<Landmark> ReconstructLandmark(const ObjectPoint& point, double depth_m,
                                             const PinholeCamera& camera,
                                             const Eigen::Isometry3d& world_from_camera) {
  if (!std::isfinite(depth_m) || depth_m <= 0.0) {
    return InvalidField("depth_m", "must be finite and > 0");
  }
  if (!(camera.fx > 0.0) || !(camera.fy > 0.0) || !std::isfinite(camera.cx) ||
      !std::isfinite(camera.cy)) {
    return InvalidField("camera", "fx, fy must be > 0 and cx, cy finite");
  }
  const Eigen::Vector3d in_camera(depth_m * (point.u - camera.cx) / camera.fx,
                                  depth_m * (point.v - camera.cy) / camera.fy, depth_m);
  Landmark l;
  l.position = world_from_camera * in_camera;
  l.scale =
      0.5 *
      ((point.box.x1 - point.box.x0) / camera.fx + (point.box.y1 - point.box.y0) / camera.fy) *
      depth_m;
  l.descriptor = point.descriptor;
  return l;
}

std::vector<Landmark> StableLandmarkTracker::AddFrame(const std::vector<Landmark>& frame) {
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(tracks_.size()),
                                            static_cast<Eigen::Index>(frame.size()));
  for (size_t t = 0; t < tracks_.size(); ++t) {
    for (size_t o = 0; o < frame.size(); ++o) {
      const double d = (tracks_[t].mean.position - frame[o].position).norm();
      const double c = CosineSimilarity(tracks_[t].mean.descriptor, frame[o].descriptor);
      if (d <= params_.gate_radius_m && c >= params_.min_descriptor_similarity) {
        // Closer and more similar observations win; strictly positive inside the gate.
        s(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(o)) =
            1.0 + c - d / params_.gate_radius_m;
      }
    }
  }
  const std::vector<int> assignment = MaxSimilarityAssignment(s);
  std::vector<Track> next;
  std::vector<bool> continued(frame.size(), false);
  std::vector<Landmark> stable;
  for (size_t t = 0; t < tracks_.size(); ++t) {
    if (assignment[t] < 0) continue;  // missed this frame: the track ends
    const Landmark& obs = frame[static_cast<size_t>(assignment[t])];
    continued[static_cast<size_t>(assignment[t])] = true;
    Track track = std::move(tracks_[t]);
    const double n = track.mean.observations;
    track.mean.position = (n * track.mean.position + obs.position) / (n + 1.0);
    track.mean.scale = (n * track.mean.scale + obs.scale) / (n + 1.0);
    for (size_t d = 0; d < track.mean.descriptor.size() && d < obs.descriptor.size(); ++d) {
      track.mean.descriptor[d] =
          static_cast<float>((n * track.mean.descriptor[d] + obs.descriptor[d]) / (n + 1.0));
    }
    track.mean.observations += 1;
    next.push_back(std::move(track));
  }
  for (size_t o = 0; o < frame.size(); ++o) {
    if (continued[o]) continue;
    Track track{frame[o], false};
    track.mean.observations = 1;
    next.push_back(std::move(track));
  }
  for (Track& track : next) {
    if (!track.reported &&
        track.mean.observations >= static_cast<uint32_t>(std::max(1, params_.min_stable_frames))) {
      track.reported = true;
      stable.push_back(track.mean);
    }
  }
  tracks_ = std::move(next);
  return stable;
}

}  // namespace semnav::relocalization
