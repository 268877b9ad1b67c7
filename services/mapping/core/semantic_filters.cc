#include "services/mapping/core/semantic_filters.h"

#include <opencv2/imgproc.hpp>

#include "services/common/geometry/kd_tree.h"

namespace semnav::mapping {

double LaplacianVariance(const cv::Mat& gray) {
  cv::Mat gray64;
  gray.convertTo(gray64, CV_64F);
  cv::Mat laplacian;
  cv::Laplacian(gray64, laplacian, CV_64F);
  cv::Scalar mean;
  cv::Scalar stddev;
  cv::meanStdDev(laplacian, mean, stddev);
  return stddev[0] * stddev[0];
}

cv::Mat ErodeSemanticMask(const cv::Mat& mask, int kernel, double keep_above) {
  cv::Mat probability;
  mask.convertTo(probability, CV_32F);
  cv::Mat sum;
  cv::filter2D(probability, sum, CV_32F, cv::Mat::ones(kernel, kernel, CV_32F), cv::Point(-1, -1),
               0.0, cv::BORDER_CONSTANT);
  cv::Mat kept = sum > keep_above;  // 255 where kept
  return kept / 255;
}

std::vector<bool> RadiusFilter(const std::vector<Eigen::Vector3f>& same_label_points, float radius,
                               int min_neighbours) {
  const geometry::KdTree<float> tree(same_label_points);
  std::vector<bool> keep(same_label_points.size());
  for (size_t i = 0; i < same_label_points.size(); ++i) {
    keep[i] =
        tree.CountCloserThan(same_label_points[i], radius) > static_cast<size_t>(min_neighbours);
  }
  return keep;
}

cv::Mat OpenSemanticLayer(const cv::Mat& layer, int kernel) {
  cv::Mat opened;
  cv::morphologyEx(layer, opened, cv::MORPH_OPEN, cv::Mat::ones(kernel, kernel, CV_8U),
                   cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  return opened;
}

}  // namespace semnav::mapping
