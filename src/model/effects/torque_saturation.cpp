#include "effect_builders.hpp"

namespace motoflex::detail {

// The motor's torque saturation (torque_saturation.hpp): τ = K_t·tanh(k·I)/k, so the torque per
// ampere falls as the current grows and never exceeds K_t/k. A servo then follows small errors
// with its full gain but drives large ones, and holds a heavy load, with less torque than its
// small-signal K_t promises, and by an amount that grows with the drive, not at a hard limit.
// Neutral at k = 0. The probe moves k to 0.75 /A (I_s = 1.33 A, a small servo's working range).
Effect torque_saturation_effect() {
  return {"torque_saturation",
          "the motor's torque saturates with the current: tau = K_t*tanh(k*I)/k, k = 1/I_s",
          "servos whose torque grows less than in proportion to the drive: large errors and "
          "heavy loads are followed more weakly than small ones, at every gain",
          {global("motor.torque_saturation_per_a", 0.15, false, 0.0, 5.0)},
          false,
          0};
}

}  // namespace motoflex::detail
