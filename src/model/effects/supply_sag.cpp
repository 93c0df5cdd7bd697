#include "effect_builders.hpp"

namespace motoflex::detail {

Effect supply_sag_effect() {
  return {"supply_sag",
          "battery voltage falling with the total motor current",
          "weaker servos when many joints draw current at once",
          {global("motor.supply_sag_ohm", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
