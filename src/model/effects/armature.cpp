#include "effect_builders.hpp"

namespace motoflex::detail {

// The reflected rotor inertia of each hinge (joint.<J>.armature_kg_m2, every law but bench;
// a slider's reflected mass joint.<J>.armature_kg is not matched by the pattern),
// the rollout's joint-space inertia row.
Effect armature_effect() {
  return {"armature",
          "rotor inertia reflected through the gear (armature) on each joint",
          "proportional to the joint acceleration: lag and overshoot growing with the command's "
          "frequency",
          {per_joint("armature_kg_m2", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
