#include "effect_builders.hpp"

namespace motoflex::detail {

// The gear's back-driving loss (friction_family.hpp): friction in proportion to the load torque
// while the load, not the motor, drives the joint; a kinetic part and a static part under the
// joint's Stribeck shape. Not one of BAM's M1-M6, which tie the loss to |K_m·τ_m − K_e·τ_e| and
// so cannot hold an arm with little current yet let the motor lift it.
Effect backdrive_friction_effect() {
  return {"backdrive_friction",
          "gear back-driving loss: friction growing with the load while the load drives",
          "an arm that holds against gravity short of the goal with little drive, and lowers "
          "slower than it lifts",
          {per_joint("backdrive_friction", 0.05), per_joint("backdrive_friction_static", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
