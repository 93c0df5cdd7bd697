#include "effect_builders.hpp"

namespace motoflex::detail {

// The driver caps the winding current: the torque stops following the duty once it reaches
// K_t·I_max, so a loaded arm stalls at the angle where that torque meets gravity and friction
// (the XL330 bench's stall). Neutral at the catalog's 1e3 A; the probe moves it two thirds of
// the way down its log range, into the currents a servo draws.
Effect current_limit_effect() {
  return {"current_limit",
          "the driver's current limit: torque capped at K_t·I_max whatever the duty",
          "arms that stall short of the goal at full duty and hold there",
          {global("motor.current_limit_a", 0.66, true, 0.05, 1.0e3)},
          false,
          0};
}

}  // namespace motoflex::detail
