#pragma once

// The uncertainty of a least-squares estimate: for residuals r(x) ∈ ℝᴺ with Jacobian J (N × p)
// at the optimum,
//
//   C = κ σ² (JᵀJ)⁻¹,   σ² = RSS / (N − p),   RSS = Σ r²,
//
// the asymptotic covariance of x (Gauss–Newton; what MuJoCo's sysid and Ceres's Covariance
// report with κ = 1). A direction JᵀJ cannot see (an eigenvalue below kRankTolerance·λ_max)
// makes the variance of every parameter with a share in it infinite: the data do not determine
// it. κ ≥ 1 is the variance inflation of correlated residuals (residual_autocorrelation.hpp):
// the residuals of joint logs are correlated from frame to frame, and with κ = 1 the intervals
// would only be a lower bound on the true uncertainty.

#include <cstddef>
#include <string>
#include <vector>

namespace motoflex {

inline constexpr double kRankTolerance = 1e-12;
inline constexpr double kConfidenceZ95 = 1.959963984540054;  // two-sided 95 %, normal

struct LeastSquaresCovariance {
  std::size_t residuals = 0;   // N
  std::size_t parameters = 0;  // p
  std::size_t rank = 0;        // of J
  double rss = 0.0;
  double sigma2 = 0.0;                          // RSS / (N − p)
  double variance_inflation = 1.0;              // κ
  std::vector<std::vector<double>> covariance;  // p × p, +inf where not determined
  // c_ij / √(c_ii c_jj); NaN where a variance is infinite or zero.
  std::vector<std::vector<double>> correlation;
  std::vector<double> standard_error;  // √c_ii
};

// `jacobian` row-major N × p. Throws std::invalid_argument for N <= p, mismatched sizes or
// κ < 1.
LeastSquaresCovariance least_squares_covariance(const std::vector<double>& jacobian,
                                                std::size_t rows, std::size_t cols, double rss,
                                                double variance_inflation);

}  // namespace motoflex
