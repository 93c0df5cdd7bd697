#include "effect_builders.hpp"

namespace motoflex::detail {

// The winding resistance follows the servo's logged housing temperature (bench law,
// motor.housing_temperature_c from each log's sidecar): R = R_25·(1 + α·(T − 25 °C)). Logs
// recorded one after another on a servo that warms up (the XL330 session: 28 °C at its first
// logs, 40 °C at its last) then drive a weaker motor the later they were taken. Copper gives
// α = 0.00393 /K when the reading is the winding's; a housing sensor that lags a hotter
// winding shows a larger α. Neutral at 0; the probe moves α to 0.005 /K.
Effect housing_temperature_effect() {
  return {"housing_temperature",
          "the winding resistance follows the logged housing temperature: "
          "R = R_25*(1 + alpha*(T - 25 C))",
          "a servo whose logs differ in strength with the temperature it logged: the later, "
          "warmer logs of a session follow their commands more weakly than the first ones",
          {global("motor.R_temperature_per_k", 0.1, false, 0.0, 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
