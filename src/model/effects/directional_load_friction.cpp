#include "effect_builders.hpp"

namespace motoflex::detail {

// BAM's directional friction (M5, bam.md §2d): K_e·τ_e apart from the motor's K_m·τ_m, read by
// the laws with the whole friction family (pd_torque, dynamixel, feetech).
Effect directional_load_friction_effect() {
  return {"directional_load_friction",
          "friction growing with the external (gravity) torque apart from the motor's (BAM's M5)",
          "a step with the sign of the joint velocity, scaled by the gravity load",
          {per_joint("load_friction_external", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
