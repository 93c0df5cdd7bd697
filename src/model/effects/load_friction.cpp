#include "effect_builders.hpp"

namespace motoflex::detail {

Effect load_friction_effect() {
  return {"load_friction",
          "friction growing with the transmitted torque (BAM's M3-M6 family)",
          "a step with the sign of the joint velocity, scaled by the load torque",
          {per_joint("load_friction", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
