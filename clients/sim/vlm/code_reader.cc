#include "clients/sim/vlm/code_reader.h"

#include <limits>
#include <opencv2/imgproc.hpp>

namespace semnav::sim::vlm {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kMaxDigits = 3;
// Mean grey-level error per pixel above which a box is not a code this reader can make out.
constexpr double kMaxMeanError = 12.0;

// first + number + last, built without operator+ (GCC 12's -Wrestrict misfires on that chain).
std::string Code(char first, const std::string& number, char last) {
  std::string code;
  code.reserve(number.size() + 2);
  code.push_back(first);
  code.append(number);
  if (last != '\0') code.push_back(last);
  return code;
}

int TextWidth(const std::string& text, double scale, int thickness) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, thickness, &baseline).width;
}

// `text` printed as the gateway prints it, in a black box of `size`.
cv::Mat Render(const std::string& text, cv::Size size, int text_height, double scale,
               int thickness) {
  cv::Mat patch(size, CV_8UC1, cv::Scalar::all(0));
  cv::putText(patch, text, cv::Point(0, text_height), kFont, scale, cv::Scalar::all(255), thickness,
              cv::LINE_AA);
  return patch;
}

double Error(const cv::Mat& a, const cv::Mat& b, const cv::Rect& columns) {
  const cv::Rect inside = columns & cv::Rect(0, 0, a.cols, a.rows);
  if (inside.area() == 0) return std::numeric_limits<double>::infinity();
  return cv::norm(a(inside), b(inside), cv::NORM_L1);
}

// The letter-digits-letter string whose rendering best reproduces `grey` (the box's pixels), or
// "" when none comes close.
std::string ReadBox(const cv::Mat& grey, int text_height, double scale, int thickness) {
  const cv::Size size = grey.size();
  std::string best;
  double best_error = std::numeric_limits<double>::infinity();
  for (char first = 'A'; first <= 'Z'; ++first) {
    for (char last = 'A'; last <= 'Z'; ++last) {
      for (int digits = 1; digits <= kMaxDigits; ++digits) {
        const std::string shape = Code(first, std::string(digits, '0'), last);
        if (std::abs(TextWidth(shape, scale, thickness) - size.width) > 2) continue;
        // Digits left to right, each judged on its own columns.
        std::string number;
        for (int d = 0; d < digits; ++d) {
          const std::string prefix = Code(first, number, '\0');
          const int start = TextWidth(prefix, scale, thickness);
          char chosen = '1';
          double chosen_error = std::numeric_limits<double>::infinity();
          for (char digit = d == 0 ? '1' : '0'; digit <= '9'; ++digit) {
            std::string candidate = prefix;
            candidate.push_back(digit);
            const int end = TextWidth(candidate, scale, thickness);
            const double e = Error(Render(candidate, size, text_height, scale, thickness), grey,
                                   cv::Rect(start, 0, end - start, size.height));
            if (e < chosen_error) {
              chosen_error = e;
              chosen = digit;
            }
          }
          number.push_back(chosen);
        }
        const std::string code = Code(first, number, last);
        const double e = Error(Render(code, size, text_height, scale, thickness), grey,
                               cv::Rect(cv::Point(0, 0), size));
        if (e < best_error) {
          best_error = e;
          best = code;
        }
      }
    }
  }
  if (best.empty() || best_error / static_cast<double>(size.area()) > kMaxMeanError) return "";
  return best;
}

}  // namespace

std::vector<PrintedCode> ReadPrintedCodes(const cv::Mat& received, const cv::Mat& raw,
                                          double font_scale, int thickness) {
  std::vector<PrintedCode> out;
  if (received.empty() || received.size() != raw.size() || received.type() != CV_8UC3 ||
      raw.type() != CV_8UC3) {
    return out;
  }
  cv::Mat diff, changed, channels[3];
  cv::absdiff(received, raw, diff);
  cv::split(diff, channels);
  cv::max(channels[0], channels[1], changed);
  cv::max(changed, channels[2], changed);
  changed = changed > 0;
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(changed, labels, stats, centroids, 8);
  int baseline = 0;
  const int text_height = cv::getTextSize("A", kFont, font_scale, thickness, &baseline).height;
  cv::Mat grey;
  cv::cvtColor(received, grey, cv::COLOR_BGR2GRAY);
  for (int c = 1; c < count; ++c) {
    const cv::Rect box(stats.at<int>(c, cv::CC_STAT_LEFT), stats.at<int>(c, cv::CC_STAT_TOP),
                       stats.at<int>(c, cv::CC_STAT_WIDTH), stats.at<int>(c, cv::CC_STAT_HEIGHT));
    const bool cut = box.x == 0 || box.y == 0 || box.x + box.width >= received.cols ||
                     box.y + box.height >= received.rows;
    if (cut || box.height < text_height || box.width < 3) continue;
    const std::string code = ReadBox(grey(box), text_height, font_scale, thickness);
    if (code.empty()) continue;
    out.push_back({code, box, cv::Point2d(box.x + box.width / 2.0, box.y + text_height / 2.0)});
  }
  return out;
}

}  // namespace semnav::sim::vlm
