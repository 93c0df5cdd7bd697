#include "effect_builders.hpp"

namespace motoflex::detail {

// The winding's Joule heating (winding_heating.hpp): the resistance rises with the winding's
// temperature, which follows I²·R through a thermal resistance and capacity, so a servo that
// stalls at full current weakens within seconds while one that tracks at low current does not.
// Neutral at R_th = 0. The probe moves R_th alone; the heat capacity keeps its value (a small
// servo's winding, 0.5 J/K) as a shape parameter, since with R_th = 0 it does nothing.
Effect winding_heating_effect() {
  return {"winding_heating",
          "winding Joule heating: the resistance rises with I^2*R through R_th and C",
          "arms that creep to a stall lower than a cold motor would hold them, after seconds at "
          "full current",
          {global("motor.winding_k_per_w", 0.3, false, 0.0, 200.0),
           global("motor.winding_heat_j_per_k", 0.0, true, 0.01, 20.0)},
          false,
          0};
}

}  // namespace motoflex::detail
