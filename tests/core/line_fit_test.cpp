// Least-squares lines against numbers worked by hand, and Student's t against its tables.

#include "motoflex/core/line_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace motoflex {
namespace {

TEST(LineFitTest, FourPointsMatchTheHandWorkedRegression) {
  // x̄ = 2.5, ȳ = 3.75, Sxx = 5, Sxy = 3.5: slope 0.7, intercept 2.0; residuals −0.7, 0.6, 0.9,
  // −0.8, RSS 2.3, σ² = 2.3/2, se(slope) = √(1.15/5), se(intercept) = √(1.15·(1/4 + 6.25/5)).
  const LineFit f = fit_line({1, 2, 3, 4}, {2, 4, 5, 4}, true);
  EXPECT_NEAR(f.slope, 0.7, 1e-12);
  EXPECT_NEAR(f.intercept, 2.0, 1e-12);
  EXPECT_NEAR(f.slope_std_error, std::sqrt(1.15 / 5.0), 1e-12);
  EXPECT_NEAR(f.intercept_std_error, std::sqrt(1.15 * (0.25 + 6.25 / 5.0)), 1e-12);
  EXPECT_NEAR(f.slope_ci95, 4.3027 * std::sqrt(1.15 / 5.0), 1e-12);  // t(2 dof)
  EXPECT_NEAR(f.residual_rms, std::sqrt(2.3 / 4.0), 1e-12);
  EXPECT_NEAR(f.r_squared, 1.0 - 2.3 / 4.75, 1e-12);  // Σ(y − ȳ)² = 4.75
}

TEST(LineFitTest, ThroughTheOriginUsesRawSumsAndOneDegreeOfFreedomLess) {
  // slope = Σxy/Σx² = (2 + 8 + 15 + 16)/30 = 41/30.
  const LineFit f = fit_line({1, 2, 3, 4}, {2, 4, 5, 4}, false);
  const double slope = 41.0 / 30.0;
  double rss = 0.0;
  for (int x = 1; x <= 4; ++x) {
    const double y[] = {2, 4, 5, 4};
    rss += std::pow(y[x - 1] - slope * x, 2);
  }
  EXPECT_NEAR(f.slope, slope, 1e-12);
  EXPECT_EQ(f.intercept, 0.0);
  EXPECT_NEAR(f.slope_std_error, std::sqrt(rss / 3.0 / 30.0), 1e-12);
  EXPECT_NEAR(f.slope_ci95, 3.1824 * f.slope_std_error, 1e-12);  // t(3 dof)
}

TEST(LineFitTest, AnExactLineHasNoResidualAndNoInterval) {
  const LineFit f = fit_line({0.5, 1.0, 2.0, 4.0}, {1.3, 2.3, 4.3, 8.3}, true);
  EXPECT_NEAR(f.slope, 2.0, 1e-12);
  EXPECT_NEAR(f.intercept, 0.3, 1e-12);
  EXPECT_NEAR(f.residual_rms, 0.0, 1e-12);
  EXPECT_NEAR(f.slope_ci95, 0.0, 1e-9);
}

TEST(LineFitTest, StudentTFollowsItsTablesAndTendsToTheNormal) {
  EXPECT_DOUBLE_EQ(student_t_975(1), 12.7062);
  EXPECT_DOUBLE_EQ(student_t_975(13), 2.1604);
  EXPECT_NEAR(student_t_975(31), 2.0395, 2e-4);  // table value
  EXPECT_NEAR(student_t_975(60), 2.0003, 2e-4);
  EXPECT_NEAR(student_t_975(120), 1.9799, 2e-4);
  EXPECT_NEAR(student_t_975(100000), 1.96, 1e-4);
  EXPECT_THROW(student_t_975(0), std::invalid_argument);
}

TEST(LineFitTest, RejectsWhatCannotBeFitted) {
  EXPECT_THROW(fit_line({1, 2}, {1, 2, 3}, false), std::invalid_argument);
  EXPECT_THROW(fit_line({1, 2}, {1, 2}, true), std::invalid_argument);  // no dof left
  EXPECT_THROW(fit_line({3, 3, 3}, {1, 2, 3}, true), std::invalid_argument);
  EXPECT_THROW(fit_line({0, 0, 0}, {1, 2, 3}, false), std::invalid_argument);
  EXPECT_THROW(fit_line({1, NAN, 3}, {1, 2, 3}, false), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
