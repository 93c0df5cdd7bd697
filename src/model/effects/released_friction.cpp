#include "effect_builders.hpp"

namespace motoflex::detail {

// A released joint's friction (released_friction.hpp): the Coulomb and viscous levels of the
// joint with its H-bridge off differ from the powered joint's, whose Coulomb level also carries
// the loaded gear mesh. Only logs that release the servo (BAM's lift_and_drop) can show it: the
// released arm swings on longer, or stops sooner, than the powered friction lets it. The probe
// lowers the released Coulomb level (by 5 % of its width, 0.02 N·m): raising it leaves an arm
// that already stops early unchanged, so a probe that way shows nothing where the effect
// matters most; the viscous change keeps its value during the probe and is fitted in the refit.
Effect released_friction_effect() {
  return {"released_friction",
          "a released servo's own friction: Coulomb and viscous levels of the joint with the "
          "H-bridge off, changed from the powered ones",
          "a released arm that swings on longer, or settles sooner, than the powered joint's "
          "friction allows",
          {per_joint("released_friction_delta_nm", -0.05),
           per_joint("released_viscous_delta_nm_s_per_rad", 0.0)},
          false,
          0};
}

}  // namespace motoflex::detail
