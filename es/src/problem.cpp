#include "motoflex_es/problem.hpp"

#include <cmath>

namespace motoflex_es {

bool Bounds::is_valid(std::string* why) const {
  const auto fail = [why](const std::string& reason) {
    if (why != nullptr) *why = reason;
    return false;
  };
  if (lower.empty()) return fail("bounds: no coordinates");
  if (lower.size() != upper.size()) {
    return fail("bounds: " + std::to_string(lower.size()) + " lower but " +
                std::to_string(upper.size()) + " upper values");
  }
  for (std::size_t i = 0; i < lower.size(); ++i) {
    if (!std::isfinite(lower[i]) || !std::isfinite(upper[i])) {
      return fail("bounds: coordinate " + std::to_string(i) + " is not finite");
    }
    if (!(lower[i] < upper[i])) {
      return fail("bounds: coordinate " + std::to_string(i) + " has lower >= upper");
    }
  }
  return true;
}

bool Bounds::contains(const std::vector<double>& x) const {
  if (x.size() != lower.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(x[i] >= lower[i] && x[i] <= upper[i])) return false;
  }
  return true;
}

double reflect_into_bounds(double value, double lower, double upper) {
  if (value >= lower && value <= upper) return value;
  if (!std::isfinite(value)) return lower + 0.5 * (upper - lower);
  const double width = upper - lower;
  double offset = std::fmod(value - lower, 2.0 * width);  // exact
  if (offset < 0.0) offset += 2.0 * width;
  if (offset > width) offset = 2.0 * width - offset;
  // Rounding in `value - lower` can leave offset a hair outside [0, width].
  if (offset < 0.0) offset = 0.0;
  if (offset > width) offset = width;
  const double reflected = lower + offset;
  return reflected > upper ? upper : reflected;
}

}  // namespace motoflex_es
