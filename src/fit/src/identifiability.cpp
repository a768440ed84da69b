#include "identifiability.hpp"

#include <cmath>

#include <fmt/format.h>

namespace plyform::fit::detail {
namespace {

// A relative change of 1 in a constant (x moves by 1: e.g. the value times e) that moves the
// fitted curves by less than this fraction of their RMS does not determine the constant.
constexpr double kInsensitive = 1e-6;
// Condition number of the column-normalised Jacobian beyond which its columns are dependent:
// (J^T J) would be 1e16, past double precision's reach.
constexpr double kDependent = 1e8;

}  // namespace

Identifiability analyse(const Eigen::MatrixXd& jacobian, double sigma2,
                        const std::vector<std::string>& names, double rms_scale) {
  const auto n = jacobian.cols();
  const auto m = jacobian.rows();
  Identifiability out;
  out.std_error.assign(static_cast<std::size_t>(n), NAN);
  out.correlation.assign(static_cast<std::size_t>(n * n), NAN);

  Eigen::VectorXd norms = jacobian.colwise().norm().transpose();
  const double scale = rms_scale * std::sqrt(static_cast<double>(m));
  bool insensitive = false;
  for (Eigen::Index j = 0; j < n; ++j) {
    if (!(norms(j) > kInsensitive * scale)) {
      out.problems.push_back(fmt::format(
          "{} is not identifiable from these curves: changing it changes the fitted traction by "
          "less than {:g} of the data's RMS (the curves do not depend on it)",
          names[static_cast<std::size_t>(j)], kInsensitive));
      insensitive = true;
    }
  }
  if (insensitive)
    return out;

  const Eigen::MatrixXd normalised = jacobian * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(normalised, Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  if (s(n - 1) * kDependent < s(0)) {
    // The right singular vector of the smallest value names the combination the data leave
    // free: the constants with a large share in it cannot be told apart.
    const Eigen::VectorXd v = svd.matrixV().col(n - 1);
    std::string which;
    for (Eigen::Index j = 0; j < n; ++j) {
      if (std::abs(v(j)) > 0.2)
        which += (which.empty() ? "" : ", ") + names[static_cast<std::size_t>(j)];
    }
    out.problems.push_back(fmt::format(
        "{} cannot be told apart by these curves (the Jacobian is singular: condition number "
        "{:.3g}); fix one of them or add curves that separate them (other rates, a hold)",
        which, s(0) / s(n - 1)));
    return out;
  }
  // (J^T J)^-1 = N^-1 V S^-2 V^T N^-1 with N = diag(norms).
  const Eigen::MatrixXd v = svd.matrixV();
  const Eigen::MatrixXd inv_normalised =
      v * s.array().square().inverse().matrix().asDiagonal() * v.transpose();
  const Eigen::MatrixXd cov = sigma2 * norms.cwiseInverse().asDiagonal() * inv_normalised *
                              norms.cwiseInverse().asDiagonal();
  for (Eigen::Index i = 0; i < n; ++i) {
    out.std_error[static_cast<std::size_t>(i)] = std::sqrt(cov(i, i));
    for (Eigen::Index j = 0; j < n; ++j) {
      out.correlation[static_cast<std::size_t>(i * n + j)] =
          inv_normalised(i, j) / std::sqrt(inv_normalised(i, i) * inv_normalised(j, j));
    }
  }
  return out;
}

}  // namespace plyform::fit::detail
