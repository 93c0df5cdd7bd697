#include "effect_builders.hpp"

namespace motoflex::detail {

// The joint's zero as its own encoder sees it differs from the zero of the load: the encoder reads
// θ + offset, θ the joint's angle from the pose the model was built in (the arm hanging straight
// down). The servo regulates on that reading and the log records it, so what changes is where
// gravity acts: the droop of a P servo, where a released arm comes to rest (at a reading of
// +offset), the load torque at every angle. BAM's q_offset with the opposite sign (BAM evaluates
// gravity at reading + q_offset; bam.md §2a). Not encoder_offset, which shifts only the logged
// angle and leaves the servo on the true one.
Effect mounting_offset_effect() {
  return {"mounting_offset",
          "the load's zero is not the encoder's zero: the servo and the log read the joint "
          "angle plus an offset",
          "a released arm that comes to rest off zero, and a servo droop that is not "
          "symmetric about the hanging pose",
          {per_joint("mounting_offset_rad", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
