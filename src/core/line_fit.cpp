#include "motoflex/core/line_fit.hpp"

#include <cmath>
#include <stdexcept>

namespace motoflex {

double student_t_975(std::size_t dof) {
  if (dof == 0) throw std::invalid_argument("Student's t needs at least one degree of freedom");
  // t_{0.975} for 1..30 degrees of freedom (standard tables), then the Cornish-Fisher expansion
  // about the normal quantile, good to 1e-4 beyond 30.
  static const double kTable[] = {12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060,
                                  2.2622,  2.2281, 2.2010, 2.1788, 2.1604, 2.1448, 2.1314, 2.1199,
                                  2.1098,  2.1009, 2.0930, 2.0860, 2.0796, 2.0739, 2.0687, 2.0639,
                                  2.0595,  2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
  if (dof <= 30) return kTable[dof - 1];
  const double z = 1.959963984540054;
  const double n = static_cast<double>(dof);
  const double z3 = z * z * z, z5 = z3 * z * z;
  return z + (z3 + z) / (4.0 * n) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * n * n);
}

LineFit fit_line(const std::vector<double>& x, const std::vector<double>& y, bool with_intercept) {
  if (x.size() != y.size()) throw std::invalid_argument("x and y differ in length");
  const std::size_t n = x.size();
  const std::size_t p = with_intercept ? 2 : 1;
  if (n <= p) throw std::invalid_argument("a line fit needs more points than coefficients");
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
      throw std::invalid_argument("a line fit needs finite values");
    }
    mean_x += x[i] / static_cast<double>(n);
    mean_y += y[i] / static_cast<double>(n);
  }
  // Centred sums with an intercept, raw sums through the origin.
  const double cx = with_intercept ? mean_x : 0.0;
  const double cy = with_intercept ? mean_y : 0.0;
  double sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - cx) * (x[i] - cx);
    sxy += (x[i] - cx) * (y[i] - cy);
  }
  if (!(sxx > 0.0)) throw std::invalid_argument("x does not vary: the slope is undetermined");
  LineFit fit;
  fit.with_intercept = with_intercept;
  fit.points = n;
  fit.slope = sxy / sxx;
  fit.intercept = with_intercept ? mean_y - fit.slope * mean_x : 0.0;
  double rss = 0.0, tss = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = y[i] - (fit.slope * x[i] + fit.intercept);
    rss += r * r;
    tss += (y[i] - mean_y) * (y[i] - mean_y);
  }
  const double dof = static_cast<double>(n - p);
  const double sigma2 = rss / dof;
  fit.slope_std_error = std::sqrt(sigma2 / sxx);
  if (with_intercept) {
    fit.intercept_std_error =
        std::sqrt(sigma2 * (1.0 / static_cast<double>(n) + mean_x * mean_x / sxx));
  }
  const double t = student_t_975(n - p);
  fit.slope_ci95 = t * fit.slope_std_error;
  fit.intercept_ci95 = t * fit.intercept_std_error;
  fit.residual_rms = std::sqrt(rss / static_cast<double>(n));
  fit.r_squared = tss > 0.0 ? 1.0 - rss / tss : 1.0;
  return fit;
}

}  // namespace motoflex
