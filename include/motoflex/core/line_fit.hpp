#pragma once

// Ordinary least squares on a straight line, y = slope·x (+ intercept), with the standard errors
// and 95 % confidence intervals of the coefficients from Student's t with n − p degrees of
// freedom (p = 1 through the origin, 2 with an intercept): the small calibration tables of a
// servo have 9–15 points, where 1.96 would understate the interval by up to 15 %.

#include <cstddef>
#include <vector>

namespace motoflex {

struct LineFit {
  bool with_intercept = false;
  std::size_t points = 0;
  double slope = 0.0;
  double intercept = 0.0;  // 0 through the origin
  double slope_std_error = 0.0;
  double intercept_std_error = 0.0;  // 0 through the origin
  double slope_ci95 = 0.0;           // half-width: slope ± slope_ci95
  double intercept_ci95 = 0.0;
  double residual_rms = 0.0;  // sqrt(Σr²/n), in y's unit
  double r_squared = 0.0;  // 1 − Σr²/Σ(y − ȳ)² (about the mean, also through the origin)
};

// Throws std::invalid_argument when x and y differ in length, there are not more points than
// coefficients, a value is not finite, or x does not vary (x all 0 through the origin).
LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, bool with_intercept);

// Student's t quantile for a two-sided 95 % interval (0.975), `dof` >= 1.
double student_t_975(std::size_t dof);

}  // namespace motoflex
