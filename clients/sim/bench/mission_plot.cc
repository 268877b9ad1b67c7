#include "clients/sim/bench/mission_plot.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace semnav::sim::bench {
namespace {

constexpr double kPixelsPerMetre = 40.0;

struct Canvas {
  const GroundTruthGrid& grid;
  cv::Mat image;
  cv::Point ToPixel(const Eigen::Vector2d& p) const {
    // Image rows grow downward; world y grows up.
    return cv::Point(static_cast<int>((p.x() - grid.origin.x()) * kPixelsPerMetre),
                     image.rows - 1 - static_cast<int>((p.y() - grid.origin.y()) * kPixelsPerMetre));
  }
};

}  // namespace

absl::Status WriteEpisodePlot(const World& world, const GroundTruthGrid& grid, const std::string& target_label,
                              const loop::EpisodeResult& result, const std::string& png_path) {
  const double scale = kPixelsPerMetre * grid.resolution;
  cv::Mat cells(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const bool occupied = grid.at(x, y) != 0;
      cells.at<cv::Vec3b>(grid.height - 1 - y, x) = occupied ? cv::Vec3b(90, 90, 90) : cv::Vec3b(250, 250, 250);
    }
  }
  Canvas canvas{grid, cv::Mat()};
  cv::resize(cells, canvas.image, cv::Size(), scale, scale, cv::INTER_NEAREST);
  for (const ObjectInstance& object : world.objects) {
    if (object.label != target_label) continue;
    cv::circle(canvas.image, canvas.ToPixel(object.box.center), static_cast<int>(kPixelsPerMetre * 1.0),
               cv::Scalar(60, 60, 230), 1, cv::LINE_AA);  // ~success radius (it counts from the footprint)
    cv::circle(canvas.image, canvas.ToPixel(object.box.center), 5, cv::Scalar(0, 0, 220), cv::FILLED);
  }
  for (size_t i = 1; i < result.trajectory.size(); ++i) {
    cv::line(canvas.image, canvas.ToPixel(result.trajectory[i - 1]), canvas.ToPixel(result.trajectory[i]),
             cv::Scalar(200, 100, 0), 2, cv::LINE_AA);
  }
  for (const Eigen::Vector2d& goal : result.goals) {  // the frontiers and targets the gateway sent it to
    cv::drawMarker(canvas.image, canvas.ToPixel(goal), cv::Scalar(0, 140, 255), cv::MARKER_DIAMOND, 9, 2);
  }
  if (!result.trajectory.empty()) {
    cv::circle(canvas.image, canvas.ToPixel(result.trajectory.front()), 6, cv::Scalar(0, 160, 0), cv::FILLED);
    cv::drawMarker(canvas.image, canvas.ToPixel(result.trajectory.back()), cv::Scalar(0, 0, 0), cv::MARKER_CROSS, 14, 2);
  }
  const std::string caption =
      absl::StrFormat("%s | find %s | %s | DTG %.2f m | path %.1f m", world.name, result.record.target,
                      result.record.success ? "SUCCESS" : "fail", result.record.distance_to_goal_m, result.record.path_m);
  // A white strip above the map keeps the caption readable on small worlds.
  cv::copyMakeBorder(canvas.image, canvas.image, 28, 0, 0, std::max(0, 520 - canvas.image.cols), cv::BORDER_CONSTANT,
                     cv::Scalar(255, 255, 255));
  cv::putText(canvas.image, caption, cv::Point(8, 19), cv::FONT_HERSHEY_SIMPLEX, 0.5, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  if (!cv::imwrite(png_path, canvas.image)) return absl::InternalError(absl::StrCat("cannot write ", png_path));
  return absl::OkStatus();
}

}  // namespace semnav::sim::bench
