// The linearity check of the covariance's Jacobian (src/fit/probe_nonlinearity.hpp): 0 for a
// linear residual, b·h/a for a quadratic one, near 1 for probes that do not belong to one
// smooth curve.

#include "probe_nonlinearity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace motoflex::detail {
namespace {

TEST(ProbeNonlinearityTest, LinearIsZeroAndQuadraticIsItsSecondOrderShare) {
  // r_m(δ) = a_m·δ + b_m·δ² with b = 0.2·a, probed at δ = ±h: s = 0.2·h exactly.
  const std::size_t n = 50;
  const double h = 0.5;
  std::vector<double> r0(n, 0.3), plus(n), minus(n), linear_plus(n), linear_minus(n);
  for (std::size_t m = 0; m < n; ++m) {
    const double a = std::sin(0.1 * static_cast<double>(m)) + 2.0, b = 0.2 * a;
    plus[m] = r0[m] + a * h + b * h * h;
    minus[m] = r0[m] - a * h + b * h * h;
    linear_plus[m] = r0[m] + a * h;
    linear_minus[m] = r0[m] - a * h;
  }
  EXPECT_NEAR(probe_nonlinearity(linear_plus.data(), linear_minus.data(), r0.data(), n), 0.0,
              1e-15);
  EXPECT_NEAR(probe_nonlinearity(plus.data(), minus.data(), r0.data(), n), 0.2 * h, 1e-12);
  // No change at all: no verdict.
  EXPECT_TRUE(std::isnan(probe_nonlinearity(r0.data(), r0.data(), r0.data(), n)));
}

TEST(ProbeNonlinearityTest, UnrelatedProbesScoreNearOne) {
  // A chaotic residual: r(x + h) and r(x − h) are two independent draws around r(x), so
  // ‖d₊ + d₋‖ and ‖d₊ − d₋‖ have the same expectation (s → 1 as n grows).
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  const std::size_t n = 20000;
  std::vector<double> r0(n), plus(n), minus(n);
  for (std::size_t m = 0; m < n; ++m) {
    r0[m] = noise(rng);
    plus[m] = r0[m] + noise(rng);
    minus[m] = r0[m] + noise(rng);
  }
  const double s = probe_nonlinearity(plus.data(), minus.data(), r0.data(), n);
  EXPECT_NEAR(s, 1.0, 0.05);
  EXPECT_GT(s, 0.5);  // above the threshold FittedParameter::kNonlinearShare
}

}  // namespace
}  // namespace motoflex::detail
