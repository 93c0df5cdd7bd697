#include "motoflex/motion/command_trajectory.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace motoflex {

CommandTrajectory::CommandTrajectory(std::vector<double> time_s, std::vector<double> angles_rad,
                                     std::size_t joints)
    : time_s_(std::move(time_s)), angles_rad_(std::move(angles_rad)), joints_(joints) {
  if (time_s_.size() < 2) throw std::invalid_argument("a trajectory needs at least 2 frames");
  if (joints_ == 0 || angles_rad_.size() != time_s_.size() * joints_) {
    throw std::invalid_argument("trajectory angles must have frames x joints entries");
  }
  for (std::size_t i = 1; i < time_s_.size(); ++i) {
    if (!(time_s_[i] > time_s_[i - 1])) {
      throw std::invalid_argument("trajectory times must strictly increase");
    }
  }
  for (const double a : angles_rad_) {
    if (!std::isfinite(a)) throw std::invalid_argument("trajectory angles must be finite");
  }
}

void CommandTrajectory::set_smoothed_supply_v(std::vector<double> supply_v) {
  if (supply_v.size() != time_s_.size()) {
    throw std::invalid_argument("the logged supply needs one value per frame");
  }
  for (const double v : supply_v) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw std::invalid_argument("a logged supply voltage must be finite and positive");
    }
  }
  supply_v_ = std::move(supply_v);
}

std::vector<double> CommandTrajectory::smoothed_supply_v(const std::vector<double>& time_s,
                                                         const std::vector<double>& logged_v) {
  if (logged_v.size() != time_s.size()) {
    throw std::invalid_argument("the logged supply needs one value per frame");
  }
  // Centred moving average over the frames within ±kSupplySmoothing_s/2 (by time, so an
  // irregular clock averages the same span), summed directly (a few tens of frames per window)
  // so that a constant supply stays exactly constant.
  const std::size_t n = logged_v.size();
  std::vector<double> out(n, 0.0);
  std::size_t lo = 0, hi = 0;  // the window is frames [lo, hi)
  const double half_s = 0.5 * kSupplySmoothing_s;
  for (std::size_t i = 0; i < n; ++i) {
    while (time_s[lo] < time_s[i] - half_s - 1e-12) ++lo;
    if (hi < i + 1) hi = i + 1;
    while (hi < n && time_s[hi] <= time_s[i] + half_s + 1e-12) ++hi;
    double sum = 0.0;
    for (std::size_t k = lo; k < hi; ++k) sum += logged_v[k];
    out[i] = sum / static_cast<double>(hi - lo);
  }
  return out;
}

double CommandTrajectory::supply_v_at(double t_s, std::size_t& hint) const {
  if (supply_v_.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t last = time_s_.size() - 1;
  if (t_s <= time_s_.front()) return supply_v_.front();
  if (t_s >= time_s_[last]) return supply_v_[last];
  if (hint >= last || time_s_[hint] > t_s) hint = 0;
  while (time_s_[hint + 1] < t_s) ++hint;
  const double w = (t_s - time_s_[hint]) / (time_s_[hint + 1] - time_s_[hint]);
  return supply_v_[hint] + w * (supply_v_[hint + 1] - supply_v_[hint]);
}

void CommandTrajectory::sample(double t_s, double* out, std::size_t& hint) const {
  const std::size_t last = time_s_.size() - 1;
  if (t_s <= time_s_.front()) {
    for (std::size_t j = 0; j < joints_; ++j) out[j] = angles_rad_[j];
    return;
  }
  if (t_s >= time_s_[last]) {
    for (std::size_t j = 0; j < joints_; ++j) out[j] = angles_rad_[last * joints_ + j];
    return;
  }
  if (hint >= last || time_s_[hint] > t_s) hint = 0;
  while (time_s_[hint + 1] < t_s) ++hint;
  const double w = (t_s - time_s_[hint]) / (time_s_[hint + 1] - time_s_[hint]);
  const double* a = &angles_rad_[hint * joints_];
  const double* b = a + joints_;
  for (std::size_t j = 0; j < joints_; ++j) out[j] = a[j] + w * (b[j] - a[j]);
}

}  // namespace motoflex
