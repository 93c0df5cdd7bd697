#include "motoflex/sim/actuator/position_firmware.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace motoflex {
namespace {

constexpr double kFirmwareCycle_s = 1e-3;

}  // namespace

PositionFirmware::PositionFirmware(const PositionFirmwareParams& params, double dt_s)
    : params_(params), cycles_per_step_(dt_s / kFirmwareCycle_s) {
  const PositionFirmwareParams& p = params_;
  if (!(p.ticks_per_rev > 0.0) || !(p.kp_divisor > 0.0) || !(p.ki_divisor > 0.0) ||
      !(p.kd_divisor > 0.0) || !(p.pwm_full_scale > 0.0)) {
    throw std::invalid_argument(
        "firmware ticks_per_rev, divisors and pwm_full_scale must be positive");
  }
  if (p.kp < 0.0 || p.ki < 0.0 || p.kd < 0.0 || p.pwm_limit < 0.0 || p.deadband_ticks < 0.0) {
    throw std::invalid_argument("firmware gains, PWM limit and dead band must not be negative");
  }
  if (!(dt_s > 0.0)) throw std::invalid_argument("firmware step must be positive");
}

double PositionFirmware::error_ticks(double goal_rad, double position_rad) const {
  const double ticks_per_rad = params_.ticks_per_rev / (2.0 * std::numbers::pi);
  double goal = goal_rad * ticks_per_rad;
  double position = position_rad * ticks_per_rad;
  if (params_.integer_ticks) {
    // The firmware sees whole encoder counts (and the goal register holds whole counts).
    goal = std::round(goal);
    position = std::round(position);
  }
  const double error = goal - position;
  if (params_.deadband_ticks > 0.0 && std::abs(error) <= params_.deadband_ticks) return 0.0;
  return error;
}

double PositionFirmware::update(double goal_rad, double position_rad) {
  const PositionFirmwareParams& p = params_;
  const double error = error_ticks(goal_rad, position_rad);
  if (first_) previous_ticks_ = error;  // no derivative kick on the first cycle
  first_ = false;
  double pwm = p.kp * error / p.kp_divisor;
  if (p.ki != 0.0) {
    sum_ticks_ += error * cycles_per_step_;
    // Anti-windup: the I term alone never exceeds the PWM limit.
    const double sum_limit = p.pwm_limit * p.ki_divisor / p.ki;
    sum_ticks_ = std::min(std::max(sum_ticks_, -sum_limit), sum_limit);
    pwm += p.ki * sum_ticks_ / p.ki_divisor;
  }
  if (p.kd != 0.0) pwm += p.kd * (error - previous_ticks_) / cycles_per_step_ / p.kd_divisor;
  previous_ticks_ = error;
  return std::min(std::max(pwm, -p.pwm_limit), p.pwm_limit) / p.pwm_full_scale;
}

}  // namespace motoflex
