#include "effect_builders.hpp"

namespace motoflex::detail {

Effect encoder_offset_effect() {
  return {"encoder_offset",
          "a constant offset of each joint's encoder (calibration error)",
          "a constant per joint, whatever the motion",
          {per_joint("encoder_offset_rad", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
