#include "motoflex/sim/joint_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace motoflex {

JointEncoder::JointEncoder(const EncoderParams& params, double physics_dt_s, RandomStream noise)
    : params_(params), noise_(std::move(noise)) {
  // Written as !(x > 0) / !(x >= 0) so that NaN is rejected too.
  if (!(physics_dt_s > 0.0)) throw std::invalid_argument("JointEncoder: physics_dt_s must be > 0");
  if (!(params.delay_s >= 0.0)) throw std::invalid_argument("JointEncoder: delay_s must be >= 0");
  if (!(params.noise_rad >= 0.0)) {
    throw std::invalid_argument("JointEncoder: noise_rad must be >= 0");
  }
  if (params.resolution_bits < 0 || params.resolution_bits > 32) {
    throw std::invalid_argument("JointEncoder: resolution_bits must be in 0..32");
  }
  if (!std::isfinite(params.offset_rad)) {
    throw std::invalid_argument("JointEncoder: offset_rad must be finite");
  }
  resolution_rad_ = params.resolution_bits == 0
                        ? 0.0
                        : std::ldexp(2.0 * std::numbers::pi, -params.resolution_bits);

  double delay_steps = params.delay_s / physics_dt_s;
  // A delay meant as a whole number of steps (10 ms at 1 ms) must read that step's angle
  // exactly, not interpolate with a weight of 1e-15 from its neighbour.
  const double nearest = std::round(delay_steps);
  if (std::abs(delay_steps - nearest) <= 1e-9 * std::max(1.0, nearest)) delay_steps = nearest;
  if (!(delay_steps < 1e7)) {
    throw std::invalid_argument("JointEncoder: delay_s is more than 1e7 physics steps");
  }
  delay_whole_steps_ = static_cast<int>(delay_steps);
  delay_fraction_ = delay_steps - delay_whole_steps_;
  // Interpolation reads the angles delay_whole_steps_ and delay_whole_steps_ + 1 pushes ago.
  history_rad_.assign(static_cast<std::size_t>(delay_whole_steps_) + 2, 0.0);
}

void JointEncoder::push(double true_angle_rad) {
  const int capacity = static_cast<int>(history_rad_.size());
  newest_ = newest_ + 1 == capacity ? 0 : newest_ + 1;
  history_rad_[static_cast<std::size_t>(newest_)] = true_angle_rad;
  stored_ = std::min(stored_ + 1, capacity);
}

double JointEncoder::stored_angle_rad(int age) const {
  if (stored_ == 0) return 0.0;
  const int capacity = static_cast<int>(history_rad_.size());
  int index = newest_ - std::min(age, stored_ - 1);
  if (index < 0) index += capacity;
  return history_rad_[static_cast<std::size_t>(index)];
}

double JointEncoder::read() {
  const double newer_rad = stored_angle_rad(delay_whole_steps_);
  const double older_rad = stored_angle_rad(delay_whole_steps_ + 1);
  // With a zero fraction this is exactly the newer angle.
  double reading_rad = newer_rad + delay_fraction_ * (older_rad - newer_rad);
  reading_rad += params_.offset_rad;
  if (resolution_rad_ > 0.0)
    reading_rad = std::round(reading_rad / resolution_rad_) * resolution_rad_;
  if (params_.noise_rad > 0.0) reading_rad += params_.noise_rad * noise_.normal();
  return reading_rad;
}

void JointEncoder::reset(double angle_rad) {
  std::fill(history_rad_.begin(), history_rad_.end(), angle_rad);
  newest_ = 0;
  stored_ = static_cast<int>(history_rad_.size());
}

}  // namespace motoflex
