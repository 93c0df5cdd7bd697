#include "effect_builders.hpp"

namespace motoflex::detail {

Effect joint_compliance_effect() {
  return {"joint_compliance",
          "elasticity of the gear train",
          "proportional to the load torque, with a resonance of the servo loop",
          {{"gear.*.spring_nm_per_rad", true, true, kNaN, kNaN, -0.3}},
          false,
          0};
}

}  // namespace motoflex::detail
