#include "clients/sim/bench/vlm_sweep_plot.h"

#include <algorithm>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"

namespace semnav::sim::bench {
namespace {

constexpr int kWidth = 640, kHeight = 460;
constexpr int kLeft = 70, kRight = 80, kTop = 50, kBottom = 110;
const cv::Scalar kSrColour(180, 110, 30);    // blue (BGR)
const cv::Scalar kPathColour(40, 100, 220);  // orange-red
const cv::Scalar kAxisColour(60, 60, 60);
const cv::Scalar kMeanPathColour(60, 150, 60);  // green

void Text(cv::Mat& image, const std::string& text, cv::Point at, double scale = 0.45,
          const cv::Scalar& colour = kAxisColour) {
  cv::putText(image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour, 1, cv::LINE_AA);
}

}  // namespace

absl::Status WriteVlmSweepPlot(const std::vector<SweepPoint>& points, const std::string& title,
                               const std::string& png_path) {
  if (points.empty()) return absl::InvalidArgumentError("points: the sweep has no point");
  double x_min = points.front().accuracy, x_max = points.front().accuracy, y_max = 1.2;
  for (const SweepPoint& p : points) {
    x_min = std::min(x_min, p.accuracy);
    x_max = std::max(x_max, p.accuracy);
    if (p.path_ratio) y_max = std::max(y_max, *p.path_ratio * 1.1);
    if (p.mean_path_ratio) y_max = std::max(y_max, *p.mean_path_ratio * 1.1);
  }
  if (x_max - x_min < 0.1) {
    x_min -= 0.05;
    x_max += 0.05;
  }
  cv::Mat image(kHeight, kWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  const int plot_w = kWidth - kLeft - kRight, plot_h = kHeight - kTop - kBottom;
  auto pixel = [&](double x, double y) {
    return cv::Point(kLeft + static_cast<int>((x - x_min) / (x_max - x_min) * plot_w),
                     kTop + plot_h - static_cast<int>(y / y_max * plot_h));
  };
  // Grid lines and y ticks every 0.2; x ticks at the sweep's accuracies.
  for (double y = 0.0; y <= y_max + 1e-9; y += 0.2) {
    cv::line(image, pixel(x_min, y), pixel(x_max, y), cv::Scalar(225, 225, 225), 1);
    Text(image, absl::StrFormat("%.1f", y), pixel(x_min, y) + cv::Point(-35, 5));
  }
  cv::line(image, pixel(x_min, 1.0), pixel(x_max, 1.0), cv::Scalar(170, 170, 170),
           1);  // ratio 1 = baseline
  for (const SweepPoint& p : points)
    Text(image, absl::StrFormat("%.2f", p.accuracy), pixel(p.accuracy, 0) + cv::Point(-15, 20));
  cv::rectangle(image, pixel(x_min, y_max), pixel(x_max, 0), kAxisColour, 1);
  Text(image, "VLM recognition accuracy (1 - miss rate; other error rates scaled with it)",
       cv::Point(kLeft, kHeight - 14), 0.42);
  Text(image, title, cv::Point(kLeft, 25), 0.5);
  // The two series: SR (filled circles) and path ratio (squares; a point only where both found).
  bool joined = false;  // a line from the previous point of the series
  cv::Point last;
  for (const SweepPoint& p : points) {
    const cv::Point at = pixel(p.accuracy, p.sr);
    if (joined) cv::line(image, last, at, kSrColour, 2, cv::LINE_AA);
    cv::circle(image, at, 5, kSrColour, cv::FILLED, cv::LINE_AA);
    Text(image, absl::StrFormat("%.2f", p.sr), at + cv::Point(6, -8), 0.4, kSrColour);
    last = at;
    joined = true;
  }
  joined = false;
  for (const SweepPoint& p : points) {
    if (!p.path_ratio) {
      joined = false;
      continue;
    }
    const cv::Point at = pixel(p.accuracy, *p.path_ratio);
    if (joined) cv::line(image, last, at, kPathColour, 2, cv::LINE_AA);
    cv::rectangle(image, at - cv::Point(5, 5), at + cv::Point(5, 5), kPathColour, cv::FILLED);
    Text(image, absl::StrFormat("%.2f (%d)", *p.path_ratio, p.paired_episodes),
         at + cv::Point(6, 16), 0.4, kPathColour);
    last = at;
    joined = true;
  }
  // Mean path over the baseline's mean path on all episodes (triangles, dashed look: thin line).
  joined = false;
  for (const SweepPoint& p : points) {
    if (!p.mean_path_ratio) {
      joined = false;
      continue;
    }
    const cv::Point at = pixel(p.accuracy, *p.mean_path_ratio);
    if (joined) cv::line(image, last, at, kMeanPathColour, 1, cv::LINE_AA);
    const std::vector<cv::Point> triangle = {at + cv::Point(0, -6), at + cv::Point(-6, 5),
                                             at + cv::Point(6, 5)};
    cv::fillConvexPoly(image, triangle, kMeanPathColour, cv::LINE_AA);
    Text(image, absl::StrFormat("%.2f", *p.mean_path_ratio), at + cv::Point(8, 4), 0.4,
         kMeanPathColour);
    last = at;
    joined = true;
  }
  // Legend: two rows under the tick labels, then the axis title.
  const int row1 = kHeight - 62, row2 = kHeight - 42;
  cv::circle(image, cv::Point(kLeft + 10, row1 - 5), 5, kSrColour, cv::FILLED, cv::LINE_AA);
  Text(image, "SR", cv::Point(kLeft + 20, row1), 0.45, kSrColour);
  cv::rectangle(image, cv::Point(kLeft + 75, row1 - 10), cv::Point(kLeft + 85, row1), kPathColour,
                cv::FILLED);
  Text(image, "path / NEAREST_FRONTIER's, episodes both found (n)", cv::Point(kLeft + 92, row1),
       0.45, kPathColour);
  const std::vector<cv::Point> triangle = {cv::Point(kLeft + 10, row2 - 11),
                                           cv::Point(kLeft + 4, row2), cv::Point(kLeft + 16, row2)};
  cv::fillConvexPoly(image, triangle, kMeanPathColour, cv::LINE_AA);
  Text(image, "mean path / NEAREST_FRONTIER's mean path, all episodes", cv::Point(kLeft + 20, row2),
       0.45, kMeanPathColour);
  if (!cv::imwrite(png_path, image))
    return absl::InternalError(absl::StrCat("cannot write ", png_path));
  return absl::OkStatus();
}

}  // namespace semnav::sim::bench
