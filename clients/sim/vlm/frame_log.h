// The camera frames the simulator sent, so the simulated VLM can answer about the frame it was
// shown. The endpoint's only input is the image it receives: it finds the recorded frame whose
// pixels that image shares (all but the printed codes), never an id the real camera lacks.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <deque>
#include <opencv2/core.hpp>
#include <optional>

#include "absl/synchronization/mutex.h"
#include "clients/sim/core/camera_model.h"
#include "clients/sim/core/sensor_frame.h"

namespace semnav::sim::vlm {

struct RecordedFrame {
  uint64_t index = 0;  // SensorFrame::index
  double time_s = 0.0;
  cv::Mat image;  // 8-bit BGR, exactly as sent
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();  // true optical pose
  CameraIntrinsics intrinsics;
};

class FrameLog {
 public:
  explicit FrameLog(size_t capacity = 64) : capacity_(capacity) {}

  // Thread-safe; frames without colour are ignored. The oldest frame leaves past capacity.
  void Record(const SensorFrame& frame);
  // The recorded frame `image` differs least from (same size), if at most `max_changed_share` of
  // its pixels differ; nullopt otherwise.
  std::optional<RecordedFrame> Match(const cv::Mat& image, double max_changed_share) const;
  size_t size() const;

 private:
  const size_t capacity_;
  mutable absl::Mutex mu_;
  std::deque<RecordedFrame> frames_ ABSL_GUARDED_BY(mu_);
};

}  // namespace semnav::sim::vlm
