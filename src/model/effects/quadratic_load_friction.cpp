#include "effect_builders.hpp"

namespace motoflex::detail {

// BAM's quadratic term (M6, bam.md §2d): s(θ̇)·(K_eq·τ_e² or K_mq·τ_m²) when motor and gravity
// oppose.
Effect quadratic_load_friction_effect() {
  return {"quadratic_load_friction",
          "stiction growing with the square of the load when motor and gravity oppose (BAM's M6)",
          "at low speed while the motor holds or lowers a load",
          {per_joint("load_friction_quad_per_nm", 0.05),
           per_joint("load_friction_external_quad_per_nm", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
