#include "motoflex/fit/parameter_covariance.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace motoflex {

LeastSquaresCovariance least_squares_covariance(const std::vector<double>& jacobian,
                                                std::size_t rows, std::size_t cols, double rss,
                                                double variance_inflation) {
  if (jacobian.size() != rows * cols) throw std::invalid_argument("covariance: J is not N x p");
  if (!(variance_inflation >= 1.0)) {
    throw std::invalid_argument("covariance: the variance inflation must be at least 1");
  }
  if (rows <= cols) throw std::invalid_argument("covariance: needs more residuals than parameters");
  const auto n = static_cast<Eigen::Index>(rows), p = static_cast<Eigen::Index>(cols);
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> j(
      jacobian.data(), n, p);
  const Eigen::MatrixXd normal = j.transpose() * j;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normal);
  const Eigen::VectorXd& lambda = eigen.eigenvalues();  // ascending
  const Eigen::MatrixXd& v = eigen.eigenvectors();
  const double lambda_max = lambda.size() > 0 ? std::max(lambda(p - 1), 0.0) : 0.0;
  const double cutoff = kRankTolerance * lambda_max;

  LeastSquaresCovariance out;
  out.residuals = rows;
  out.parameters = cols;
  out.rss = rss;
  out.sigma2 = rss / static_cast<double>(rows - cols);
  out.variance_inflation = variance_inflation;
  // (JᵀJ)⁺ over the directions the data see; a parameter with a share in an unseen direction
  // has no finite variance.
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(p, p);
  std::vector<bool> undetermined(cols, false);
  for (Eigen::Index k = 0; k < p; ++k) {
    if (lambda(k) > cutoff && lambda_max > 0.0) {
      inverse += v.col(k) * v.col(k).transpose() / lambda(k);
      ++out.rank;
    } else {
      for (Eigen::Index i = 0; i < p; ++i) {
        if (std::abs(v(i, k)) > 1e-6) undetermined[static_cast<std::size_t>(i)] = true;
      }
    }
  }
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  out.covariance.assign(cols, std::vector<double>(cols, 0.0));
  out.correlation.assign(cols, std::vector<double>(cols, nan));
  out.standard_error.assign(cols, inf);
  for (std::size_t a = 0; a < cols; ++a) {
    for (std::size_t b = 0; b < cols; ++b) {
      const bool unseen = undetermined[a] || undetermined[b];
      out.covariance[a][b] =
          unseen ? (a == b ? inf : nan)
                 : variance_inflation * out.sigma2 *
                       inverse(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    }
  }
  for (std::size_t a = 0; a < cols; ++a) {
    if (!undetermined[a]) out.standard_error[a] = std::sqrt(std::max(out.covariance[a][a], 0.0));
  }
  for (std::size_t a = 0; a < cols; ++a) {
    for (std::size_t b = 0; b < cols; ++b) {
      const double scale = out.standard_error[a] * out.standard_error[b];
      if (std::isfinite(scale) && scale > 0.0) out.correlation[a][b] = out.covariance[a][b] / scale;
    }
  }
  return out;
}

}  // namespace motoflex
