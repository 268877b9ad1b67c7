#include "clients/sim/vlm/frame_log.h"

#include <opencv2/imgproc.hpp>

namespace semnav::sim::vlm {

void FrameLog::Record(const SensorFrame& frame) {
  if (!frame.rgb.has_value() || frame.rgb->empty()) return;
  RecordedFrame record{frame.index, frame.time_s, frame.rgb->clone(), frame.world_from_camera,
                       frame.intrinsics};
  absl::MutexLock lock(&mu_);
  frames_.push_back(std::move(record));
  while (frames_.size() > capacity_) frames_.pop_front();
}

std::optional<RecordedFrame> FrameLog::Match(const cv::Mat& image, double max_changed_share) const {
  if (image.empty() || image.type() != CV_8UC3) return std::nullopt;
  absl::MutexLock lock(&mu_);
  const RecordedFrame* best = nullptr;
  int best_changed = 0;
  cv::Mat diff, changed, channels[3];
  // Newest first: a robot standing still sends identical frames, and the newest is the one asked.
  for (auto it = frames_.rbegin(); it != frames_.rend(); ++it) {
    if (it->image.size() != image.size() || it->image.type() != image.type()) continue;
    cv::absdiff(it->image, image, diff);
    cv::split(diff, channels);
    cv::max(channels[0], channels[1], changed);
    cv::max(changed, channels[2], changed);
    const int count = cv::countNonZero(changed);
    if (best == nullptr || count < best_changed) {
      best = &*it;
      best_changed = count;
    }
  }
  if (best == nullptr || best_changed > max_changed_share * static_cast<double>(image.total()))
    return std::nullopt;
  RecordedFrame out = *best;
  out.image = best->image.clone();
  return out;
}

size_t FrameLog::size() const {
  absl::MutexLock lock(&mu_);
  return frames_.size();
}

}  // namespace semnav::sim::vlm
