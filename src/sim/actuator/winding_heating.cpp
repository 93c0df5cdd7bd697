#include "motoflex/sim/actuator/winding_heating.hpp"

#include <cmath>

#include "motoflex/core/error.hpp"

namespace motoflex {

WindingTemperature::WindingTemperature(const WindingHeatingParams& params, double dt_s)
    : thermal_resistance_k_per_w_(params.thermal_resistance_k_per_w), decay_(0.0) {
  if (!(params.thermal_resistance_k_per_w >= 0.0)) {
    throw ModelError("motor.winding_k_per_w must not be negative");
  }
  if (!(params.heat_capacity_j_per_k > 0.0)) {
    throw ModelError("motor.winding_heat_j_per_k must be positive");
  }
  if (!(dt_s > 0.0)) throw ModelError("winding heating: the physics step must be positive");
  if (heats()) {
    decay_ = std::exp(-dt_s / (params.thermal_resistance_k_per_w * params.heat_capacity_j_per_k));
  }
}

void WindingTemperature::advance(double current_a, double resistance_ohm) {
  if (!heats()) return;
  const double settled_k = current_a * current_a * resistance_ohm * thermal_resistance_k_per_w_;
  rise_k_ = settled_k + (rise_k_ - settled_k) * decay_;
}

}  // namespace motoflex
