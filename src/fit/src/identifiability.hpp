#pragma once
// Statistics of a least-squares optimum from its Jacobian: standard errors sigma^2 (J^T J)^-1,
// correlations, and the constants the curves do not determine (a zero or dependent column).

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace plyform::fit::detail {

struct Identifiability {
  std::vector<double> std_error;    ///< of each optimiser variable x
  std::vector<double> correlation;  ///< n x n, row-major
  std::vector<std::string> problems;
};

/// `jacobian`: d residual / d x (m x n) at the optimum; `sigma2`: the residual variance
/// SSR / (m - n); `names` of the constants; `rms_scale`: the size of the data (their RMS), so
/// that a column is "zero" relative to the curves it fits.
[[nodiscard]] Identifiability analyse(const Eigen::MatrixXd& jacobian, double sigma2,
                                      const std::vector<std::string>& names, double rms_scale);

}  // namespace plyform::fit::detail
