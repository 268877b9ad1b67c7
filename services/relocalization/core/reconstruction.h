#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "absl/status/statusor.h"
#include "services/relocalization/core/landmark.h"
#include "services/relocalization/core/object_points.h"

namespace semnav::relocalization {

// Pinhole intrinsics in pixels.
struct PinholeCamera {
  double fx = 0, fy = 0, cx = 0, cy = 0;
};

// Object point + depth at its centre + camera pose -> 3D landmark (seed 001, 1.1):
// position = world_from_camera * (depth (u - cx) / fx, depth (v - cy) / fy, depth),
// scale = mean of box width x depth / fx and box height x depth / fy (metres).
// INVALID_ARGUMENT naming "depth_m" / "camera" for non-positive or non-finite input.
absl::StatusOr<Landmark> ReconstructLandmark(const ObjectPoint& point, double depth_m,
                                             const PinholeCamera& camera,
                                             const Eigen::Isometry3d& world_from_camera);

// Keeps only object points tracked over consecutive frames (seed 001, 1.1).
struct TrackerParams {
  int min_stable_frames = 3;               // consecutive observations before a landmark is kept
  double gate_radius_m = 0.3;              // an observation continues a track within this distance
  double min_descriptor_similarity = 0.7;  // ... and with at least this cosine similarity
};

// Associates each frame's reconstructed landmarks with the running tracks (Hungarian on
// a gated position/descriptor similarity); a track missed in a frame ends. A track is
// reported once, as the mean of its observations, in the frame it becomes stable.
class StableLandmarkTracker {
 public:
  explicit StableLandmarkTracker(const TrackerParams& params) : params_(params) {}

  // Returns the landmarks that became stable with this frame.
  std::vector<Landmark> AddFrame(const std::vector<Landmark>& frame);

 private:
  struct Track {
    Landmark mean;  // observation-averaged landmark; mean.observations = track length
    bool reported = false;
  };
  TrackerParams params_;
  std::vector<Track> tracks_;
};

}  // namespace semnav::relocalization
