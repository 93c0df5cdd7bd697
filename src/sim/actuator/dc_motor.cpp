#include "motoflex/sim/actuator/dc_motor.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace motoflex {

DcMotor::DcMotor(const DcMotorParams& params, double dt_s) : params_(params), dt_s_(dt_s) {
  // Written as !(x > 0) so that NaN is rejected too.
  if (!(dt_s > 0.0)) throw std::invalid_argument("DcMotor: dt_s must be > 0");
  if (!(params.resistance_ohm > 0.0)) {
    throw std::invalid_argument("DcMotor: resistance_ohm must be > 0");
  }
  if (!(params.inductance_h >= 0.0)) {
    throw std::invalid_argument("DcMotor: inductance_h must be >= 0");
  }
  // The clamp below needs −U_bat <= +U_bat.
  if (!(params.supply_v >= 0.0)) throw std::invalid_argument("DcMotor: supply_v must be >= 0");
  update_lag_fraction();
}

void DcMotor::update_lag_fraction() {
  // Seed 001, Algorithm 1, line 5: the RL circuit relaxes toward U with time constant L/R.
  // −expm1(−x) is 1 − exp(−x) without cancellation when dt·R/L is small; L = 0 gives x = ∞
  // and a fraction of exactly 1 (no lag).
  lag_fraction_ = params_.inductance_h == 0.0
                      ? 1.0
                      : -std::expm1(-dt_s_ * params_.resistance_ohm / params_.inductance_h);
}

void DcMotor::set_operating_point(double supply_v, double resistance_ohm) {
  if (!(resistance_ohm > 0.0)) throw std::invalid_argument("DcMotor: resistance_ohm must be > 0");
  if (!(supply_v >= 0.0)) throw std::invalid_argument("DcMotor: supply_v must be >= 0");
  params_.supply_v = supply_v;
  if (resistance_ohm != params_.resistance_ohm) {
    params_.resistance_ohm = resistance_ohm;
    update_lag_fraction();
  }
}

double DcMotor::update(double commanded_v, double motor_speed_rad_s) {
  // Seed 001, Algorithm 1, lines 2–4, made symmetric: the H-bridge limits both polarities.
  const double voltage_v = std::min(std::max(commanded_v, -params_.supply_v), params_.supply_v);
  // Algorithm 1, line 5.
  resistor_voltage_v_ += (voltage_v - resistor_voltage_v_) * lag_fraction_;
  // Algorithm 1, line 6: torque from the current, minus back-EMF and viscous friction (the
  // paper lumps both into one speed-proportional term because both only depend on ω_m).
  return resistor_voltage_v_ / params_.resistance_ohm * params_.stiffness *
             params_.torque_constant_nm_per_a -
         params_.viscous_nm_s_per_rad * motor_speed_rad_s;
}

double DcMotor::stall_torque_nm() const {
  // Same operation order as update(), so a settled stall matches this value bit for bit.
  return params_.supply_v / params_.resistance_ohm * params_.stiffness *
         params_.torque_constant_nm_per_a;
}

}  // namespace motoflex
