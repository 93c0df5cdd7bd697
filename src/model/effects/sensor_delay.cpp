#include "effect_builders.hpp"

namespace motoflex::detail {

Effect sensor_delay_effect() {
  return {"sensor_delay",
          "the logged angles lag the joint by a transport delay",
          "minus the joint velocity times the delay; the cross-correlation of "
          "measured and simulated angles peaks at a positive lag",
          {global("sensor.delay_s", 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
