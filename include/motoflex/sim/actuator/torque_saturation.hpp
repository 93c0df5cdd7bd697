#pragma once

// The motor's torque saturation (the effect torque_saturation): the torque stops rising in
// proportion to the winding current as the current grows (magnetic saturation of the motor's
// iron, a driver that regulates its current softly rather than at a hard limit),
//   τ = K_t·I_s·tanh(I/I_s) = K_t·tanh(k·I)/k,   k = 1/I_s   (motor.torque_saturation_per_a)
// so the small-current torque constant is K_t and the torque never exceeds K_t·I_s. k = 0 is
// the linear motor, exactly (no tanh is evaluated). Unlike the driver's current limit
// (motor.current_limit_a, a hard clamp on the current) the gain falls gradually: at I = I_s the
// torque is tanh(1) = 76 % of the linear one.

#include <cmath>

namespace motoflex {

// The torque-producing current for a winding current current_a (A); saturation_per_a = k ≥ 0.
inline double saturated_current_a(double current_a, double saturation_per_a) {
  if (!(saturation_per_a > 0.0)) return current_a;
  return std::tanh(saturation_per_a * current_a) / saturation_per_a;
}

}  // namespace motoflex
