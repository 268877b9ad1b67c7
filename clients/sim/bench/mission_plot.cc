#include "clients/sim/bench/mission_plot.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <set>
#include <vector>

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
    return cv::Point(
        static_cast<int>((p.x() - grid.origin.x()) * kPixelsPerMetre),
        image.rows - 1 - static_cast<int>((p.y() - grid.origin.y()) * kPixelsPerMetre));
  }
};

// Occupied cells dark, free cells white; with `explored`, free cells the robot's map never
// observed are tinted blue-grey.
Canvas GridCanvas(const GroundTruthGrid& grid, const GroundTruthGrid* explored) {
  const double scale = kPixelsPerMetre * grid.resolution;
  cv::Mat cells(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const bool unexplored = explored != nullptr && explored->at(x, y) == 0;
      cv::Vec3b colour = grid.at(x, y) != 0 ? cv::Vec3b(90, 90, 90)
                         : unexplored       ? cv::Vec3b(225, 205, 190)
                                            : cv::Vec3b(250, 250, 250);
      cells.at<cv::Vec3b>(grid.height - 1 - y, x) = colour;
    }
  }
  Canvas canvas{grid, cv::Mat()};
  cv::resize(cells, canvas.image, cv::Size(), scale, scale, cv::INTER_NEAREST);
  return canvas;
}

std::vector<cv::Point> Footprint(const Canvas& canvas, const BoxShape& box) {
  const Eigen::Vector2d half = box.size.head<2>() / 2.0;
  const Eigen::Rotation2Dd rotation(box.yaw);
  std::vector<cv::Point> corners;
  for (const Eigen::Vector2d& corner :
       {Eigen::Vector2d(half.x(), half.y()), Eigen::Vector2d(-half.x(), half.y()),
        Eigen::Vector2d(-half.x(), -half.y()), Eigen::Vector2d(half.x(), -half.y())}) {
    corners.push_back(canvas.ToPixel(box.center + rotation * corner));
  }
  return corners;
}

// Footprints under the path: detected ones filled green and named, the others light grey.
void DrawObjects(Canvas& canvas, const World& world, const std::set<int>& seen) {
  for (int i = 0; i < static_cast<int>(world.objects.size()); ++i) {
    const std::vector<cv::Point> corners = Footprint(canvas, world.objects[i].box);
    if (seen.contains(i)) {
      cv::fillConvexPoly(canvas.image, corners, cv::Scalar(170, 225, 170), cv::LINE_AA);
      cv::polylines(canvas.image, corners, true, cv::Scalar(40, 130, 40), 1, cv::LINE_AA);
    } else {  // lighter than the walls, so furniture reads as furniture
      cv::fillConvexPoly(canvas.image, corners, cv::Scalar(185, 185, 185), cv::LINE_AA);
      cv::polylines(canvas.image, corners, true, cv::Scalar(120, 120, 120), 1, cv::LINE_AA);
    }
  }
  for (const int i : seen) {  // names last, so no footprint covers them
    if (i < 0 || i >= static_cast<int>(world.objects.size())) continue;
    cv::putText(canvas.image, world.objects[i].label,
                canvas.ToPixel(world.objects[i].box.center) + cv::Point(-12, 3),
                cv::FONT_HERSHEY_SIMPLEX, 0.33, cv::Scalar(20, 90, 20), 1, cv::LINE_AA);
  }
}

void DrawEpisode(Canvas& canvas, const World& world, const std::string& target_label,
                 const loop::EpisodeResult& result) {
  for (const ObjectInstance& object : world.objects) {
    if (object.label != target_label) continue;
    cv::circle(canvas.image, canvas.ToPixel(object.box.center),
               static_cast<int>(kPixelsPerMetre * 1.0), cv::Scalar(60, 60, 230), 1,
               cv::LINE_AA);  // ~success radius (it counts from the footprint)
    cv::circle(canvas.image, canvas.ToPixel(object.box.center), 5, cv::Scalar(0, 0, 220),
               cv::FILLED);
  }
  for (size_t i = 1; i < result.trajectory.size(); ++i) {
    cv::line(canvas.image, canvas.ToPixel(result.trajectory[i - 1]),
             canvas.ToPixel(result.trajectory[i]), cv::Scalar(200, 100, 0), 2, cv::LINE_AA);
  }
  for (const Eigen::Vector2d& goal :
       result.goals) {  // the frontiers and targets the gateway sent it to
    cv::drawMarker(canvas.image, canvas.ToPixel(goal), cv::Scalar(0, 140, 255), cv::MARKER_DIAMOND,
                   9, 2);
  }
  if (!result.trajectory.empty()) {
    cv::circle(canvas.image, canvas.ToPixel(result.trajectory.front()), 6, cv::Scalar(0, 160, 0),
               cv::FILLED);
    cv::drawMarker(canvas.image, canvas.ToPixel(result.trajectory.back()), cv::Scalar(0, 0, 0),
                   cv::MARKER_CROSS, 14, 2);
  }
}

// A white strip above the map keeps the caption readable on small worlds.
void AddCaption(Canvas& canvas, const World& world, const loop::EpisodeResult& result) {
  const std::string caption =
      absl::StrFormat("%s | find %s | %s | DTG %.2f m | path %.1f m", world.name,
                      result.record.target, result.record.success ? "SUCCESS" : "fail",
                      result.record.distance_to_goal_m, result.record.path_m);
  cv::copyMakeBorder(canvas.image, canvas.image, 28, 0, 0, std::max(0, 520 - canvas.image.cols),
                     cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255));
  cv::putText(canvas.image, caption, cv::Point(8, 19), cv::FONT_HERSHEY_SIMPLEX, 0.5,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
}

absl::Status Write(const Canvas& canvas, const std::string& png_path) {
  if (!cv::imwrite(png_path, canvas.image))
    return absl::InternalError(absl::StrCat("cannot write ", png_path));
  return absl::OkStatus();
}

}  // namespace

absl::Status WriteEpisodePlot(const World& world, const GroundTruthGrid& grid,
                              const std::string& target_label, const loop::EpisodeResult& result,
                              const std::string& png_path) {
  Canvas canvas = GridCanvas(grid, nullptr);
  DrawEpisode(canvas, world, target_label, result);
  AddCaption(canvas, world, result);
  return Write(canvas, png_path);
}

absl::Status WriteExplorationPlot(const World& world, const GroundTruthGrid& grid,
                                  const GroundTruthGrid& explored, const std::string& target_label,
                                  const loop::EpisodeResult& result, const std::string& png_path) {
  if (explored.width != grid.width || explored.height != grid.height) {
    return absl::InvalidArgumentError("the explored mask must have the layout of the world grid");
  }
  Canvas canvas = GridCanvas(grid, &explored);
  DrawObjects(canvas, world, result.seen_objects);
  DrawEpisode(canvas, world, target_label, result);
  // Wide enough for the legend under the map (one swatch or marker per element) and the caption.
  cv::copyMakeBorder(canvas.image, canvas.image, 0, 0, 0, std::max(0, 760 - canvas.image.cols),
                     cv::BORDER_CONSTANT, cv::Scalar(255, 255, 255));
  AddCaption(canvas, world, result);
  const int top = canvas.image.rows;
  cv::copyMakeBorder(canvas.image, canvas.image, 0, 44, 0, 0, cv::BORDER_CONSTANT,
                     cv::Scalar(255, 255, 255));
  const auto text = [&](const std::string& words, int x, int y) {
    cv::putText(canvas.image, words, cv::Point(x + 14, y + 4), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  };
  int y = top + 14;
  cv::circle(canvas.image, cv::Point(12, y), 6, cv::Scalar(0, 160, 0), cv::FILLED);
  text("start", 12, y);
  cv::line(canvas.image, cv::Point(70, y), cv::Point(86, y), cv::Scalar(200, 100, 0), 2,
           cv::LINE_AA);
  text("path", 78, y);
  cv::drawMarker(canvas.image, cv::Point(140, y), cv::Scalar(0, 0, 0), cv::MARKER_CROSS, 12, 2);
  text("end", 140, y);
  cv::drawMarker(canvas.image, cv::Point(190, y), cv::Scalar(0, 140, 255), cv::MARKER_DIAMOND, 9,
                 2);
  text("goals the gateway sent", 190, y);
  cv::circle(canvas.image, cv::Point(380, y), 5, cv::Scalar(0, 0, 220), cv::FILLED);
  cv::circle(canvas.image, cv::Point(380, y), 10, cv::Scalar(60, 60, 230), 1, cv::LINE_AA);
  text(absl::StrCat("target (", target_label, ") and ~1 m success radius"), 384, y);
  y += 20;
  cv::rectangle(canvas.image, cv::Point(6, y - 6), cv::Point(18, y + 6), cv::Scalar(170, 225, 170),
                cv::FILLED);
  text("object the robot detected", 12, y);
  cv::rectangle(canvas.image, cv::Point(220, y - 6), cv::Point(232, y + 6),
                cv::Scalar(185, 185, 185), cv::FILLED);
  text("object never detected", 226, y);
  cv::rectangle(canvas.image, cv::Point(400, y - 6), cv::Point(412, y + 6),
                cv::Scalar(225, 205, 190), cv::FILLED);
  text("free space its map never observed", 406, y);
  return Write(canvas, png_path);
}

}  // namespace semnav::sim::bench
