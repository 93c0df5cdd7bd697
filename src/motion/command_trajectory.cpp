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
