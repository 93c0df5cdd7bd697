#include "effect_builders.hpp"

namespace motoflex::detail {

// BAM's load-dependent Stribeck term (M4/M5, bam.md §2d): s(θ̇)·|K_ms·τ_m − K_es·τ_e|.
Effect load_stribeck_friction_effect() {
  return {"load_stribeck_friction",
          "load-dependent stiction: breakaway friction growing with the load (BAM's M4/M5)",
          "large at reversals and standstill under load, vanishing at speed",
          {per_joint("load_friction_stribeck", 0.05),
           per_joint("load_friction_external_stribeck", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
