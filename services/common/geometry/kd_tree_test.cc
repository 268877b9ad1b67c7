#include "services/common/geometry/kd_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace semnav::geometry {
namespace {

TEST(KdTreeTest, HandPlacedPoints) {
  const KdTree<double> tree({{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {5, 5, 5}});
  EXPECT_EQ(tree.Nearest({0.9, 0.1, 0}, 2), (std::vector<size_t>{1, 0}));
  EXPECT_EQ(tree.WithinRadius({0, 0, 0}, 2.0), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(tree.Nearest({0, 0, 0}, 10).size(), 5u);
  EXPECT_TRUE(tree.Nearest({0, 0, 0}, 0).empty());
  EXPECT_TRUE(KdTree<double>().WithinRadius({0, 0, 0}, 1.0).empty());
}

TEST(KdTreeTest, CountCloserThanExcludesTheBoundary) {
  // Distances from the origin: 0, 1, 2, 3, 8.66.
  const KdTree<float> tree({{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {5, 5, 5}});
  EXPECT_EQ(tree.CountCloserThan({0, 0, 0}, 2.0f), 2u);  // 0 and 1; 2 lies on the boundary
  EXPECT_EQ(tree.CountCloserThan({0, 0, 0}, 2.01f), 3u);
  EXPECT_EQ(tree.CountCloserThan({0, 0, 0}, 0.5f), 1u);  // the query point itself
  EXPECT_EQ(tree.CountCloserThan({0, 0, 0}, 100.0f), 5u);
  EXPECT_EQ(KdTree<float>().CountCloserThan({0, 0, 0}, 1.0f), 0u);
}

TEST(KdTreeTest, AgreesWithBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  std::vector<Eigen::Vector3d> points(500);
  for (auto& p : points) p = {u(rng), u(rng), u(rng) * 0.1};
  const KdTree<double> tree(points);
  std::vector<Eigen::Vector3f> points_f;
  for (const auto& p : points) points_f.push_back(p.cast<float>());
  const KdTree<float> tree_f(points_f);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d q(u(rng), u(rng), u(rng) * 0.1);
    std::vector<size_t> order(points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      return (points[a] - q).squaredNorm() < (points[b] - q).squaredNorm();
    });
    EXPECT_EQ(tree.Nearest(q, 7), std::vector<size_t>(order.begin(), order.begin() + 7));
    std::vector<size_t> inside;
    for (size_t i : order) {
      if ((points[i] - q).norm() <= 2.5) inside.push_back(i);
    }
    EXPECT_EQ(tree.WithinRadius(q, 2.5), inside);
    const Eigen::Vector3f qf = q.cast<float>();
    size_t closer = 0;
    for (const auto& p : points_f) closer += (p - qf).squaredNorm() < 2.5f * 2.5f ? 1 : 0;
    EXPECT_EQ(tree_f.CountCloserThan(qf, 2.5f), closer);
  }
}

}  // namespace
}  // namespace semnav::geometry
