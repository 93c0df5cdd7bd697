#include "motoflex/studies/titan/settling.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace motoflex {
namespace {

void check_series(const std::vector<double>& time_s, const std::vector<double>& values) {
  if (time_s.empty() || time_s.size() != values.size()) {
    throw std::invalid_argument("settling: time and value series must be non-empty and equal");
  }
}

}  // namespace

double settling_time_s(const std::vector<double>& time_s, const std::vector<double>& values,
                       double final_value, double band, double from_s) {
  check_series(time_s, values);
  if (!(band >= 0.0)) throw std::invalid_argument("settling: band must be >= 0");
  // Walk back from the end to the last sample outside the band.
  for (std::size_t k = values.size(); k-- > 0;) {
    if (time_s[k] < from_s) break;
    if (!(std::abs(values[k] - final_value) <= band)) {
      if (k + 1 == values.size()) return std::numeric_limits<double>::infinity();
      return time_s[k + 1];
    }
  }
  return from_s;
}

double tail_mean(const std::vector<double>& time_s, const std::vector<double>& values,
                 double window_s) {
  check_series(time_s, values);
  const double from = time_s.back() - window_s;
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t k = values.size(); k-- > 0 && time_s[k] >= from;) {
    sum += values[k];
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : values.back();
}

}  // namespace motoflex
