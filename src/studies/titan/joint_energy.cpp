#include "motoflex/studies/titan/joint_energy.hpp"

#include <cmath>
#include <numeric>

namespace motoflex {

JointEnergyMeter::JointEnergyMeter(std::size_t channels)
    : work_j_(channels, 0.0), absolute_work_j_(channels, 0.0) {}

void JointEnergyMeter::add(std::size_t channel, double power_w, double dt_s) {
  work_j_.at(channel) += power_w * dt_s;
  absolute_work_j_.at(channel) += std::abs(power_w) * dt_s;
}

double JointEnergyMeter::total_work_j() const {
  return std::accumulate(work_j_.begin(), work_j_.end(), 0.0);
}

double JointEnergyMeter::averaged_absolute_power_w(std::size_t channel) const {
  return duration_s_ > 0.0 ? absolute_work_j(channel) / duration_s_ : 0.0;
}

double JointEnergyMeter::averaged_absolute_power_w() const {
  // Seed 000 eq. 8.
  if (!(duration_s_ > 0.0)) return 0.0;
  return std::accumulate(absolute_work_j_.begin(), absolute_work_j_.end(), 0.0) / duration_s_;
}

}  // namespace motoflex
