#include "effect_builders.hpp"

namespace motoflex::detail {

Effect backlash_effect() {
  return {"backlash",
          "play in the gear train",
          "a dead band at every reversal of the load torque",
          {{"gear.*.backlash_rad", true, true, 1.0e-6, 0.05, 0.5}},
          false,
          0};
}

}  // namespace motoflex::detail
