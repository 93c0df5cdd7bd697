#include "motoflex/sim/actuator/h_bridge_motor.hpp"

#include <algorithm>

#include "motoflex/sim/actuator/torque_saturation.hpp"

namespace motoflex {

HBridgeMotorOutput h_bridge_motor(const HBridgeMotorParams& params, double duty,
                                  double joint_rate_rad_s) {
  const double kt = params.torque_constant_nm_per_a;
  const double back_emf_v = kt * params.gear_ratio * joint_rate_rad_s;
  if (params.current_limit_a > 0.0 && params.supply_v > 0.0) {
    const double window = params.resistance_ohm * params.current_limit_a;
    duty = std::min(std::max(duty, (back_emf_v - window) / params.supply_v),
                    (back_emf_v + window) / params.supply_v);
    // The window may lie beyond what the bridge can give (fast back-driving): full duty then.
    duty = std::min(std::max(duty, -1.0), 1.0);
  }
  HBridgeMotorOutput out;
  out.current_a = (params.supply_v * duty - back_emf_v) / params.resistance_ohm;
  out.torque_nm =
      params.gear_ratio * kt * saturated_current_a(out.current_a, params.saturation_per_a);
  return out;
}

}  // namespace motoflex
