#include "services/mapping/core/semantic_filters.h"

#include <gtest/gtest.h>

namespace semnav::mapping {
namespace {

TEST(SemanticFiltersTest, LaplacianVarianceOfSingleDot) {
  cv::Mat image = cv::Mat::zeros(5, 5, CV_32F);
  image.at<float>(2, 2) = 1.0f;
  // Laplacian: -4 at the dot, +1 at its 4 neighbours, 0 elsewhere: mean 0, variance (16 + 4) / 25.
  EXPECT_NEAR(LaplacianVariance(image), 0.8, 1e-9);
  EXPECT_NEAR(LaplacianVariance(cv::Mat::ones(5, 5, CV_32F)), 0.0, 1e-12);
}

TEST(SemanticFiltersTest, ErosionKeepsOnlyPixelsWithFullNeighbourhood) {
  cv::Mat mask = cv::Mat::zeros(20, 20, CV_8U);
  mask(cv::Rect(5, 5, 10, 10)) = 1;
  mask.at<uint8_t>(1, 1) = 1;  // isolated outlier
  const cv::Mat eroded = ErodeSemanticMask(mask);
  EXPECT_EQ(cv::countNonZero(eroded), 36);  // the 10x10 block shrinks by 2 on each side
  EXPECT_EQ(eroded.at<uint8_t>(7, 7), 1);
  EXPECT_EQ(eroded.at<uint8_t>(6, 6), 0);
  EXPECT_EQ(eroded.at<uint8_t>(1, 1), 0);
}

TEST(SemanticFiltersTest, ErosionWeighsSemanticProbability) {
  cv::Mat confident = cv::Mat::zeros(20, 20, CV_32F);
  confident(cv::Rect(5, 5, 10, 10)) = 0.96;  // 25 * 0.96 = 24 > 23.5
  EXPECT_EQ(cv::countNonZero(ErodeSemanticMask(confident)), 36);
  cv::Mat unsure = cv::Mat::zeros(20, 20, CV_32F);
  unsure(cv::Rect(5, 5, 10, 10)) = 0.9;  // 25 * 0.9 = 22.5 < 23.5
  EXPECT_EQ(cv::countNonZero(ErodeSemanticMask(unsure)), 0);
}

TEST(SemanticFiltersTest, RadiusFilterNeedsMoreThanFiveNeighbours) {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i < 6; ++i) points.emplace_back(0.01f * i, 0.0f, 0.0f);  // 6 within 0.1 m: kept
  for (int i = 0; i < 5; ++i)
    points.emplace_back(5.0f + 0.01f * i, 0.0f, 0.0f);  // 5 within 0.1 m: dropped
  points.emplace_back(0.0f, 0.11f, 0.0f);               // 0.11 m from the cluster: alone
  const std::vector<bool> keep = RadiusFilter(points, 0.1f, 5);
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(keep[i]) << i;
  for (int i = 6; i < 12; ++i) EXPECT_FALSE(keep[i]) << i;
}

TEST(SemanticFiltersTest, OpeningRemovesSpecksAndKeepsBlocks) {
  cv::Mat layer = cv::Mat::zeros(12, 12, CV_8U);
  layer(cv::Rect(2, 2, 5, 5)) = 1;
  layer.at<uint8_t>(10, 10) = 1;
  const cv::Mat opened = OpenSemanticLayer(layer);
  EXPECT_EQ(cv::countNonZero(opened), 25);
  EXPECT_EQ(opened.at<uint8_t>(10, 10), 0);
}

}  // namespace
}  // namespace semnav::mapping
