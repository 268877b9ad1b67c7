#include "services/relocalization/core/kd_tree.h"

#include <algorithm>
#include <random>

#include <gtest/gtest.h>

namespace semnav::relocalization {
namespace {

TEST(RelocKdTreeTest, HandPlacedPoints) {
  const KdTree tree({{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {5, 5, 5}});
  EXPECT_EQ(tree.Nearest({0.9, 0.1, 0}, 2), (std::vector<size_t>{1, 0}));
  EXPECT_EQ(tree.WithinRadius({0, 0, 0}, 2.0), (std::vector<size_t>{0, 1, 2}));
  EXPECT_EQ(tree.Nearest({0, 0, 0}, 10).size(), 5u);
  EXPECT_TRUE(tree.Nearest({0, 0, 0}, 0).empty());
  EXPECT_TRUE(KdTree().WithinRadius({0, 0, 0}, 1.0).empty());
}

TEST(RelocKdTreeTest, AgreesWithBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  std::vector<Eigen::Vector3d> points(500);
  for (auto& p : points) p = {u(rng), u(rng), u(rng) * 0.1};
  const KdTree tree(points);
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
  }
}

}  // namespace
}  // namespace semnav::relocalization
