#pragma once

#include <Eigen/Core>
#include <vector>

namespace semnav::relocalization {

// Optimal assignment (Hungarian algorithm, O(n^2 m)) maximising the summed similarity
// of a rows x cols matrix. Returns each row's column, or -1 when the row is left
// unassigned; a pair whose similarity is <= 0 is never reported (seed 001, 3.1: a
// zero score means "must not match").
std::vector<int> MaxSimilarityAssignment(const Eigen::MatrixXd& similarity);

}  // namespace semnav::relocalization
