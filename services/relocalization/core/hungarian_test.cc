#include "services/relocalization/core/hungarian.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <set>

namespace semnav::relocalization {
namespace {

double Total(const Eigen::MatrixXd& s, const std::vector<int>& a) {
  double total = 0.0;
  for (size_t r = 0; r < a.size(); ++r) {
    if (a[r] >= 0) total += s(static_cast<Eigen::Index>(r), a[r]);
  }
  return total;
}

// Best total over every injective partial row -> column map (brute force).
double BruteForceBest(const Eigen::MatrixXd& s, Eigen::Index row, std::vector<bool>& used) {
  if (row == s.rows()) return 0.0;
  double best = BruteForceBest(s, row + 1, used);  // row left unassigned
  for (Eigen::Index c = 0; c < s.cols(); ++c) {
    if (used[static_cast<size_t>(c)] || s(row, c) <= 0.0) continue;
    used[static_cast<size_t>(c)] = true;
    best = std::max(best, s(row, c) + BruteForceBest(s, row + 1, used));
    used[static_cast<size_t>(c)] = false;
  }
  return best;
}

TEST(RelocHungarianTest, BeatsGreedyOnHandMadeMatrix) {
  Eigen::MatrixXd s(2, 2);
  s << 0.9, 0.8, 0.85, 0.1;
  // Greedy would take 0.9 + 0.1 = 1.0; the optimum crosses over: 0.8 + 0.85.
  EXPECT_EQ(MaxSimilarityAssignment(s), (std::vector<int>{1, 0}));
}

TEST(RelocHungarianTest, ZeroSimilarityIsNeverMatched) {
  Eigen::MatrixXd s(2, 2);
  s << 0.0, 0.5, 0.0, 0.4;
  EXPECT_EQ(MaxSimilarityAssignment(s), (std::vector<int>{1, -1}));
}

TEST(RelocHungarianTest, RectangularBothWays) {
  Eigen::MatrixXd tall(3, 2);
  tall << 0.2, 0.1, 0.9, 0.3, 0.8, 0.7;
  EXPECT_EQ(MaxSimilarityAssignment(tall), (std::vector<int>{-1, 0, 1}));
  EXPECT_EQ(MaxSimilarityAssignment(tall.transpose()), (std::vector<int>{1, 2}));
}

TEST(RelocHungarianTest, EmptyMatrix) {
  EXPECT_EQ(MaxSimilarityAssignment(Eigen::MatrixXd(0, 3)).size(), 0u);
  EXPECT_EQ(MaxSimilarityAssignment(Eigen::MatrixXd(2, 0)), (std::vector<int>{-1, -1}));
}

TEST(RelocHungarianTest, MatchesBruteForceOnRandomSmallMatrices) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> value(0.0, 1.0);
  std::uniform_int_distribution<int> dim(1, 5);
  for (int trial = 0; trial < 400; ++trial) {
    Eigen::MatrixXd s(dim(rng), dim(rng));
    for (Eigen::Index r = 0; r < s.rows(); ++r) {
      for (Eigen::Index c = 0; c < s.cols(); ++c) {
        s(r, c) = value(rng) < 0.3 ? 0.0 : value(rng);  // sparse like gated similarities
      }
    }
    const std::vector<int> a = MaxSimilarityAssignment(s);
    ASSERT_EQ(a.size(), static_cast<size_t>(s.rows()));
    std::set<int> cols;
    for (size_t r = 0; r < a.size(); ++r) {
      if (a[r] < 0) continue;
      EXPECT_GT(s(static_cast<Eigen::Index>(r), a[r]), 0.0);
      EXPECT_TRUE(cols.insert(a[r]).second) << "column used twice";
    }
    std::vector<bool> used(static_cast<size_t>(s.cols()), false);
    EXPECT_NEAR(Total(s, a), BruteForceBest(s, 0, used), 1e-9) << "trial " << trial << "\n" << s;
  }
}

// Similarities from absurd coordinates are NaN or infinite: they used to make the augmenting
// search spin forever (one Relocalize request pinned a core). They now count as "no match".
TEST(RelocHungarianTest, NonFiniteSimilaritiesAreNoMatchAndTerminate) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  Eigen::MatrixXd s(2, 2);
  s << nan, 0.5, 0.7, nan;
  EXPECT_EQ(MaxSimilarityAssignment(s), (std::vector<int>{1, 0}));
  s << nan, nan, nan, nan;
  EXPECT_EQ(MaxSimilarityAssignment(s), (std::vector<int>{-1, -1}));
  Eigen::MatrixXd wide(1, 2);
  wide << inf, 0.2;
  EXPECT_EQ(MaxSimilarityAssignment(wide), (std::vector<int>{1}));
  Eigen::MatrixXd tall(3, 1);  // more rows than columns: the transposed path
  tall << nan, 0.4, -inf;
  EXPECT_EQ(MaxSimilarityAssignment(tall), (std::vector<int>{-1, 0, -1}));
}

}  // namespace
}  // namespace semnav::relocalization
