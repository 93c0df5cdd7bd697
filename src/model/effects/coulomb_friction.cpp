#include "effect_builders.hpp"

namespace motoflex::detail {

Effect coulomb_friction_effect() {
  return {"coulomb_friction",
          "velocity-independent dry friction in each joint",
          "a step with the sign of the joint velocity",
          {per_joint("friction_nm", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
