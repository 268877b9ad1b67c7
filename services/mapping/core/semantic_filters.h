#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

namespace semnav::mapping {

// Variance of the 3x3 Laplacian of a grey image (seed 002 blur filter): low = blurred.
double LaplacianVariance(const cv::Mat& gray);

// Seed 004 correction 1: M_new = (1_5x5 * M) > 23.5. `mask` holds per-pixel semantic probability
// (CV_32F in [0, 1]) or 0/1 (CV_8U); returns CV_8U 0/1. Pixels outside the image count as 0.
cv::Mat ErodeSemanticMask(const cv::Mat& mask, int kernel = 5, double keep_above = 23.5);

// Seed 004 correction 2: keep point p iff sum over p' of I(|p - p'| < radius) > min_neighbours,
// p' ranging over the same-label points (p itself included, as in the seed's formula).
std::vector<bool> RadiusFilter(const std::vector<Eigen::Vector3f>& same_label_points, float radius,
                               int min_neighbours);

// Seed 004 correction 3: morphological opening of one label's 2D map (CV_8U 0/1), k x k ones.
cv::Mat OpenSemanticLayer(const cv::Mat& layer, int kernel = 3);

}  // namespace semnav::mapping
