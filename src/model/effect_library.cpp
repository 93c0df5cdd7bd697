#include "motoflex/model/effect_library.hpp"

#include "effects/effect_builders.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex {

// Every effect is one file in src/model/effects/ (its parameters, bounds and probe) plus one
// line here; its hook in the simulator is the parameter names a servo law or the rollout reads
// (src/sim/effect_hooks.cpp), and its residual signature is probed by src/effects/.
const std::vector<Effect>& effect_library() {
  static const std::vector<Effect> library = {
      detail::encoder_offset_effect(),
      detail::encoder_scale_effect(),
      detail::sensor_delay_effect(),
      detail::coulomb_friction_effect(),
      detail::viscous_friction_effect(),
      detail::stribeck_effect(),
      detail::load_friction_effect(),
      detail::backlash_effect(),
      detail::joint_compliance_effect(),
      detail::link_flexibility_effect(),
      detail::resistance_drift_effect(),
      detail::supply_sag_effect(),
      detail::ground_compliance_effect(),
      detail::foot_slip_effect(),
      // Appended, so that the order above (and the loop's ties) stays.
      detail::directional_load_friction_effect(),
      detail::load_stribeck_friction_effect(),
      detail::quadratic_load_friction_effect(),
      detail::armature_effect(),
      detail::current_limit_effect(),
      detail::backdrive_friction_effect(),
      detail::mounting_offset_effect(),
      detail::winding_heating_effect(),
      detail::torque_saturation_effect(),
      detail::housing_temperature_effect(),
      detail::servo_derivative_effect(),
      detail::released_friction_effect(),
  };
  return library;
}

const Effect& find_effect(const std::string& name, const std::string& source, int line,
                          const std::string& field) {
  for (const Effect& effect : effect_library()) {
    if (effect.name == name) return effect;
  }
  std::string known;
  for (const Effect& effect : effect_library()) {
    known += (known.empty() ? "" : ", ") + effect.name;
  }
  throw InputError(source, line, field, "unknown effect '" + name + "' (known: " + known + ")");
}

}  // namespace motoflex
