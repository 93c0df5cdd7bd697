#pragma once

// How far a residual vector is from linear in one coordinate over a central-difference step:
// with d± = r(x ± h) − r(x),
//
//   s = ‖d₊ + d₋‖ / ‖d₊ − d₋‖,
//
// the second-order change against the first-order one. For r = a·δ + b·δ² it is |b|·h/|a| (0
// for a linear residual); where r is not smooth at the scale h (a chaotic walk, where any
// small change sends the late trajectory elsewhere) d₊ and d₋ are unrelated and s is near 1.
// NaN when r does not change (d₊ = d₋).

#include <cmath>
#include <cstddef>
#include <limits>

namespace motoflex::detail {

inline double probe_nonlinearity(const double* plus, const double* minus, const double* r0,
                                 std::size_t n) {
  double second = 0.0, first = 0.0;
  for (std::size_t m = 0; m < n; ++m) {
    const double sum = (plus[m] - r0[m]) + (minus[m] - r0[m]), difference = plus[m] - minus[m];
    second += sum * sum;
    first += difference * difference;
  }
  return first > 0.0 ? std::sqrt(second / first) : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace motoflex::detail
