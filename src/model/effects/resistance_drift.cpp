#include "effect_builders.hpp"

namespace motoflex::detail {

Effect resistance_drift_effect() {
  return {"resistance_drift",
          "motor resistance rising over the run (winding heat)",
          "a servo error that grows with time and with the load",
          {global("motor.R_drift_per_s", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
