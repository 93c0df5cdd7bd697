#include "effect_builders.hpp"

namespace motoflex::detail {

Effect stribeck_effect() {
  return {"stribeck",
          "stiction: extra breakaway friction at low joint speed",
          "large near velocity reversals and standstill, vanishing at speed",
          {per_joint("stribeck_nm", 0.05), per_joint("stribeck_velocity_rad_s", 0.0, true)},
          false,
          0};
}

}  // namespace motoflex::detail
