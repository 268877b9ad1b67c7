#include "services/relocalization/core/hungarian.h"

#include <cmath>
#include <limits>

namespace semnav::relocalization {
namespace {

// Minimum-cost assignment of every row of `cost` (rows <= cols) by shortest augmenting
// paths with row/column potentials. Returns the column of each row.
std::vector<int> MinCostRowAssignment(const Eigen::MatrixXd& cost) {
  const int n = static_cast<int>(cost.rows());
  const int m = static_cast<int>(cost.cols());
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // 1-based potentials; column 0 is the virtual source of each augmentation.
  std::vector<double> u(n + 1, 0.0), v(m + 1, 0.0);
  std::vector<int> row_of_col(m + 1, 0), previous(m + 1, 0);
  for (int row = 1; row <= n; ++row) {
    row_of_col[0] = row;
    int col = 0;
    std::vector<double> slack(m + 1, kInf);
    std::vector<bool> visited(m + 1, false);
    do {
      visited[col] = true;
      const int r = row_of_col[col];
      double delta = kInf;
      int next = 0;
      for (int j = 1; j <= m; ++j) {
        if (visited[j]) continue;
        const double reduced = cost(r - 1, j - 1) - u[r] - v[j];
        if (reduced < slack[j]) {
          slack[j] = reduced;
          previous[j] = col;
        }
        if (slack[j] < delta) {
          delta = slack[j];
          next = j;
        }
      }
      for (int j = 0; j <= m; ++j) {
        if (visited[j]) {
          u[row_of_col[j]] += delta;
          v[j] -= delta;
        } else {
          slack[j] -= delta;
        }
      }
      col = next;
    } while (row_of_col[col] != 0);
    do {  // flip the augmenting path back to the source
      const int before = previous[col];
      row_of_col[col] = row_of_col[before];
      col = before;
    } while (col != 0);
  }
  std::vector<int> col_of_row(n, -1);
  for (int j = 1; j <= m; ++j) {
    if (row_of_col[j] != 0) col_of_row[row_of_col[j] - 1] = j - 1;
  }
  return col_of_row;
}

}  // namespace

std::vector<int> MaxSimilarityAssignment(const Eigen::MatrixXd& similarity) {
  const Eigen::Index rows = similarity.rows(), cols = similarity.cols();
  std::vector<int> result(static_cast<size_t>(rows), -1);
  if (rows == 0 || cols == 0) return result;
  // Negative scores can never help, so they cost the same as "no match" (0). So does a
  // non-finite score: a NaN cost never lowers a slack, and the augmenting search looped forever.
  const Eigen::MatrixXd cost =
      -similarity.unaryExpr([](double s) { return std::isfinite(s) && s > 0.0 ? s : 0.0; });
  if (rows <= cols) {
    result = MinCostRowAssignment(cost);
  } else {
    const std::vector<int> row_of_col = MinCostRowAssignment(cost.transpose());
    for (Eigen::Index c = 0; c < cols; ++c)
      result[static_cast<size_t>(row_of_col[c])] = static_cast<int>(c);
  }
  for (Eigen::Index r = 0; r < rows; ++r) {
    const int c = result[static_cast<size_t>(r)];
    if (c >= 0 && !(cost(r, c) < 0.0)) result[static_cast<size_t>(r)] = -1;
  }
  return result;
}

}  // namespace semnav::relocalization
