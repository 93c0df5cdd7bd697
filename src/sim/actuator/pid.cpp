#include "motoflex/sim/actuator/pid.hpp"

#include <stdexcept>

#include "motoflex/core/error.hpp"

namespace motoflex {

Pid::Pid(const PidGains& gains, double dt_s) : gains_(gains), dt_s_(dt_s) {
  // Written as !(dt > 0) so that a NaN step is rejected too.
  if (!(dt_s > 0.0)) throw std::invalid_argument("Pid: dt_s must be > 0");
}

// Seed 001, Algorithm 1, line 1: U = PID(q_T, q_A).
double Pid::update(double error_rad) {
  // The integral includes the current error, so a constant error e gives exactly the ramp
  // ki·e·t at t = k·dt after k updates.
  integral_rad_s_ += error_rad * dt_s_;
  // No previous error after reset(): a zero derivative avoids a kick of kd·e/dt.
  const double error_rate_rad_s = has_previous_ ? (error_rad - previous_error_rad_) / dt_s_ : 0.0;
  previous_error_rad_ = error_rad;
  has_previous_ = true;
  return gains_.kp_v_per_rad * error_rad + gains_.ki_v_per_rad_s * integral_rad_s_ +
         gains_.kd_v_s_per_rad * error_rate_rad_s;
}

void Pid::reset() {
  integral_rad_s_ = 0.0;
  previous_error_rad_ = 0.0;
  has_previous_ = false;
}

void Pid::preload_integral(double output_v) {
  if (gains_.ki_v_per_rad_s == 0.0) {
    // Without an integral term no stored state can produce a voltage at zero error; starting
    // "settled" would silently start unsettled instead.
    if (output_v == 0.0) {
      integral_rad_s_ = 0.0;
      return;
    }
    throw ModelError("Pid::preload_integral: ki is 0, so no integral can hold a nonzero output");
  }
  integral_rad_s_ = output_v / gains_.ki_v_per_rad_s;
}

}  // namespace motoflex
