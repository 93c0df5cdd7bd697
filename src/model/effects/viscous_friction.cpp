#include "effect_builders.hpp"

namespace motoflex::detail {

Effect viscous_friction_effect() {
  return {"viscous_friction",
          "friction proportional to the joint velocity",
          "proportional to the joint velocity, filtered by the servo loop",
          {per_joint("viscous_nm_s_per_rad", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
