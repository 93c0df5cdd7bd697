// The variance inflation of correlated residuals (residual_autocorrelation.hpp): its layout
// arithmetic, and that κσ²(JᵀJ)⁻¹ matches the true spread of a least-squares estimate under
// AR(1) noise where σ²(JᵀJ)⁻¹ does not.

#include "motoflex/fit/residual_autocorrelation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "motoflex/fit/parameter_covariance.hpp"

namespace motoflex {
namespace {

TEST(ResidualAutocorrelationTest, LagsRunAlongFramesWithinAChannelAndNeverAcrossTwoLogs) {
  // One channel, one series 1, 1, 1, 1: Σ r_t r_t−1 = 3, Σ r² = 4, ρ = 0.75, κ = 7.
  const ResidualAutocorrelation one = residual_autocorrelation({1, 1, 1, 1}, {4}, 1);
  EXPECT_DOUBLE_EQ(one.lag1, 0.75);
  EXPECT_DOUBLE_EQ(one.inflation, 7.0);
  EXPECT_DOUBLE_EQ(one.effective, 4.0 / 7.0);
  // The same values as two logs of two frames: one lag each, ρ = 2/4.
  EXPECT_DOUBLE_EQ(residual_autocorrelation({1, 1, 1, 1}, {2, 2}, 1).lag1, 0.5);
  // Two channels of opposite sign, frame-major: each channel is constant (ρ = 4/6); a lag
  // taken across channels would see −1 instead.
  const ResidualAutocorrelation two = residual_autocorrelation({1, -1, 1, -1, 1, -1}, {3}, 2);
  EXPECT_DOUBLE_EQ(two.lag1, 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(two.inflation, 5.0);
}

TEST(ResidualAutocorrelationTest, AlternatingOrZeroResidualsKeepTheNominalCovariance) {
  const ResidualAutocorrelation alternating = residual_autocorrelation({1, -1, 1, -1}, {4}, 1);
  EXPECT_DOUBLE_EQ(alternating.lag1, -0.75);
  EXPECT_DOUBLE_EQ(alternating.inflation, 1.0);  // never narrower than the white-noise interval
  EXPECT_DOUBLE_EQ(residual_autocorrelation({0, 0, 0}, {3}, 1).inflation, 1.0);
  // A constant series is capped short of ρ = 1 (κ finite).
  std::vector<double> constant(100000, 1.0);
  const ResidualAutocorrelation c = residual_autocorrelation(constant, {100000}, 1);
  EXPECT_LT(c.lag1, 1.0);
  EXPECT_TRUE(std::isfinite(c.inflation));
  EXPECT_THROW(residual_autocorrelation({1, 2, 3}, {2}, 1), std::invalid_argument);
  EXPECT_THROW(residual_autocorrelation({1, 2}, {2}, 0), std::invalid_argument);
  EXPECT_THROW(least_squares_covariance({1, 0, 1, 1, 1, 2}, 3, 2, 1.0, 0.5), std::invalid_argument);
}

// y = a + b·t + e, t = 0..T−1, e AR(1) with ρ = 0.9 (e_t = ρ e_t−1 + √(1 − ρ²) w_t). Over 300
// independent noise draws the slope estimates spread with some standard deviation; the
// standard error each fit reports should match it. With κ from the fit's own residuals it
// does (within 25 %); without, it is √κ ≈ 4.4 times too small.
TEST(ResidualAutocorrelationTest, InflatedStandardErrorMatchesTheSpreadOfEstimatesUnderAr1Noise) {
  constexpr int kSamples = 1000, kDraws = 300;
  constexpr double kRho = 0.9, kA = 0.5, kB = 0.002;
  std::mt19937_64 rng(20261129);
  std::normal_distribution<double> white(0.0, 1.0);
  std::vector<double> j(2 * kSamples);
  for (int t = 0; t < kSamples; ++t) {
    j[2 * t] = 1.0;
    j[2 * t + 1] = t;
  }
  // Closed-form least squares for a line.
  const double n = kSamples, st = n * (n - 1) / 2, stt = (n - 1) * n * (2 * n - 1) / 6;
  const double det = n * stt - st * st;
  std::vector<double> slopes, nominal_se, inflated_se;
  for (int d = 0; d < kDraws; ++d) {
    std::vector<double> y(kSamples);
    double e = white(rng);
    for (int t = 0; t < kSamples; ++t) {
      if (t > 0) e = kRho * e + std::sqrt(1 - kRho * kRho) * white(rng);
      y[t] = kA + kB * t + e;
    }
    double sy = 0, sty = 0;
    for (int t = 0; t < kSamples; ++t) {
      sy += y[t];
      sty += t * y[t];
    }
    const double b = (n * sty - st * sy) / det, a = (sy - b * st) / n;
    std::vector<double> r(kSamples);
    double rss = 0;
    for (int t = 0; t < kSamples; ++t) {
      r[t] = y[t] - a - b * t;
      rss += r[t] * r[t];
    }
    const ResidualAutocorrelation rho = residual_autocorrelation(r, {kSamples}, 1);
    slopes.push_back(b);
    nominal_se.push_back(least_squares_covariance(j, kSamples, 2, rss, 1.0).standard_error[1]);
    inflated_se.push_back(
        least_squares_covariance(j, kSamples, 2, rss, rho.inflation).standard_error[1]);
  }
  double mean = 0, var = 0;
  for (const double b : slopes) mean += b / kDraws;
  for (const double b : slopes) var += (b - mean) * (b - mean) / (kDraws - 1);
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  const double spread = std::sqrt(var);
  EXPECT_NEAR(mean, kB, 3 * spread / std::sqrt(kDraws));  // unbiased
  EXPECT_NEAR(median(inflated_se) / spread, 1.0, 0.25);
  EXPECT_LT(median(nominal_se) / spread, 0.35);  // the white-noise interval: far too narrow
}

}  // namespace
}  // namespace motoflex
