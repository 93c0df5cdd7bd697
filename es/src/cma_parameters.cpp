// CMA-ES options validation and the strategy parameters that depend on n and λ only.

#include <algorithm>
#include <cmath>
#include <string>

#include "motoflex_es/cma_es.hpp"

namespace motoflex_es {

bool CmaEsOptions::is_valid(std::string* why) const {
  const auto fail = [why](const std::string& reason) {
    if (why != nullptr) *why = reason;
    return false;
  };
  if (!(initial_sigma_relative > 0.0) || !std::isfinite(initial_sigma_relative)) {
    return fail("initial_sigma_relative must be finite and > 0");
  }
  if (population_size == 1) return fail("population_size must be 0 (default) or at least 2");
  if (!(population_increase >= 1.0) || !std::isfinite(population_increase)) {
    return fail("population_increase must be finite and >= 1");
  }
  if (std::isnan(target_fitness)) return fail("target_fitness must not be NaN");
  if (!(tol_fun >= 0.0)) return fail("tol_fun must be >= 0");
  if (!(tol_x >= 0.0)) return fail("tol_x must be >= 0");
  if (!(tol_stall_relative >= 0.0)) return fail("tol_stall_relative must be >= 0");
  if (!(max_condition > 1.0)) return fail("max_condition must be > 1");
  return true;
}

CmaParameters cma_parameters(std::size_t n, std::size_t lambda, bool active) {
  // Hansen 2016, Table 1 and eq. 49–53 (α_cov = 2, c_m = 1).
  CmaParameters p;
  const double nd = static_cast<double>(n);
  p.lambda = lambda;
  p.mu = lambda / 2;
  const double lambda_d = static_cast<double>(lambda);
  Eigen::VectorXd raw(static_cast<Eigen::Index>(lambda));
  for (std::size_t i = 0; i < lambda; ++i) {
    raw(static_cast<Eigen::Index>(i)) =
        std::log((lambda_d + 1.0) / 2.0) - std::log(static_cast<double>(i + 1));
  }
  double positive_sum = 0.0, positive_squares = 0.0, negative_sum = 0.0, negative_squares = 0.0;
  for (Eigen::Index i = 0; i < raw.size(); ++i) {
    if (raw(i) > 0.0) {
      positive_sum += raw(i);
      positive_squares += raw(i) * raw(i);
    } else {
      negative_sum += -raw(i);
      negative_squares += raw(i) * raw(i);
    }
  }
  p.mueff = positive_sum * positive_sum / positive_squares;
  const double mueff_minus =
      negative_squares > 0.0 ? negative_sum * negative_sum / negative_squares : 0.0;
  p.cc = (4.0 + p.mueff / nd) / (nd + 4.0 + 2.0 * p.mueff / nd);
  p.cs = (p.mueff + 2.0) / (nd + p.mueff + 5.0);
  p.c1 = 2.0 / ((nd + 1.3) * (nd + 1.3) + p.mueff);
  p.cmu = std::min(1.0 - p.c1,
                   2.0 * (p.mueff - 2.0 + 1.0 / p.mueff) / ((nd + 2.0) * (nd + 2.0) + p.mueff));
  p.damps = 1.0 + 2.0 * std::max(0.0, std::sqrt((p.mueff - 1.0) / (nd + 1.0)) - 1.0) + p.cs;
  p.chi_n = std::sqrt(nd) * (1.0 - 1.0 / (4.0 * nd) + 1.0 / (21.0 * nd * nd));

  // eq. 53: negative weights scaled so that the update keeps C positive definite.
  const double alpha_mu = 1.0 + p.c1 / p.cmu;
  const double alpha_mueff = 1.0 + 2.0 * mueff_minus / (p.mueff + 2.0);
  const double alpha_posdef = (1.0 - p.c1 - p.cmu) / (nd * p.cmu);
  const double negative_scale = std::min({alpha_mu, alpha_mueff, alpha_posdef});
  p.weights.resize(raw.size());
  for (Eigen::Index i = 0; i < raw.size(); ++i) {
    if (raw(i) >= 0.0) {
      p.weights(i) = raw(i) / positive_sum;
    } else {
      p.weights(i) = active && negative_sum > 0.0 ? negative_scale * raw(i) / negative_sum : 0.0;
    }
  }
  p.eigen_interval = std::max<std::uint64_t>(
      1, static_cast<std::uint64_t>(std::floor(1.0 / (10.0 * nd * (p.c1 + p.cmu)))));
  p.max_iterations =
      static_cast<std::uint64_t>(100.0 + 150.0 * (nd + 3.0) * (nd + 3.0) / std::sqrt(lambda_d));
  return p;
}

}  // namespace motoflex_es
