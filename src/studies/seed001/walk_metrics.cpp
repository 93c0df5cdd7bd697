#include "motoflex/studies/seed001/walk_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motoflex {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// x at t by linear interpolation; NaN outside the samples.
double sample_at(const std::vector<double>& time_s, const std::vector<double>& x, double t) {
  if (time_s.empty() || t < time_s.front() || t > time_s.back()) return kNaN;
  const auto upper = std::lower_bound(time_s.begin(), time_s.end(), t);
  const std::size_t i = static_cast<std::size_t>(upper - time_s.begin());
  if (i == 0 || time_s[i] == t) return x[i];
  const double u = (t - time_s[i - 1]) / (time_s[i] - time_s[i - 1]);
  return x[i - 1] + u * (x[i] - x[i - 1]);
}

}  // namespace

double mean_speed_mm_s(const std::vector<double>& time_s, const std::vector<double>& x_m,
                       double t0_s, double t1_s) {
  if (!(t1_s > t0_s)) return kNaN;
  return 1000.0 * (sample_at(time_s, x_m, t1_s) - sample_at(time_s, x_m, t0_s)) / (t1_s - t0_s);
}

std::vector<double> window_ranges(const std::vector<double>& time_s,
                                  const std::vector<double>& signal, double start_s, double end_s,
                                  double period_s) {
  std::vector<double> ranges;
  if (!(period_s > 0.0)) return ranges;
  // A small tolerance so that a window ending exactly at end_s (a step boundary) counts.
  const double tolerance_s = 1e-9 * std::max(1.0, std::abs(end_s));
  for (int k = 0;; ++k) {
    const double from = start_s + k * period_s;
    const double to = from + period_s;
    if (to > end_s + tolerance_s) break;
    double low = std::numeric_limits<double>::infinity();
    double high = -low;
    std::size_t count = 0;
    for (std::size_t i = 0; i < time_s.size(); ++i) {
      if (time_s[i] < from - tolerance_s || time_s[i] >= to - tolerance_s) continue;
      low = std::min(low, signal[i]);
      high = std::max(high, signal[i]);
      ++count;
    }
    if (count >= 2) ranges.push_back(high - low);
  }
  return ranges;
}

double alternation_ratio(const std::vector<double>& ranges) {
  if (ranges.size() < 2) return kNaN;
  double sum[2] = {0.0, 0.0};
  int count[2] = {0, 0};
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    sum[k % 2] += ranges[k];
    ++count[k % 2];
  }
  const double even = sum[0] / count[0];
  const double odd = sum[1] / count[1];
  if (!(even > 0.0) || !(odd > 0.0)) return kNaN;
  return std::max(even / odd, odd / even);
}

const char* to_string(FallDirection direction) {
  switch (direction) {
    case FallDirection::kForward:
      return "forward";
    case FallDirection::kBackward:
      return "backward";
    case FallDirection::kLeft:
      return "left";
    case FallDirection::kRight:
      return "right";
  }
  return "forward";
}

FallDirection fall_direction(double roll_rad, double pitch_rad) {
  if (std::abs(pitch_rad) >= std::abs(roll_rad)) {
    return pitch_rad >= 0.0 ? FallDirection::kForward : FallDirection::kBackward;
  }
  return roll_rad > 0.0 ? FallDirection::kRight : FallDirection::kLeft;
}

}  // namespace motoflex
