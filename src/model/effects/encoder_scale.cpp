#include "effect_builders.hpp"

namespace motoflex::detail {

Effect encoder_scale_effect() {
  return {"encoder_scale",
          "an encoder or gear-ratio scale error of each joint",
          "proportional to the joint angle",
          {per_joint("encoder_scale", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
