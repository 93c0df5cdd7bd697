#pragma once

// Internal to the effect library: what the effect files (src/model/effects/<name>.cpp, one per
// effect) build their entries with.

#include <limits>
#include <string>

#include "motoflex/model/effect_library.hpp"

namespace motoflex::detail {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// A parameter of every actuated joint, `joint.*.<leaf>`, one free value per joint.
inline EffectParameter per_joint(const std::string& leaf, double probe_fraction,
                                 bool log_scale = false, double lower = kNaN, double upper = kNaN) {
  return {"joint.*." + leaf, true, log_scale, lower, upper, probe_fraction};
}

// One robot-wide parameter.
inline EffectParameter global(const std::string& name, double probe_fraction,
                              bool log_scale = false, double lower = kNaN, double upper = kNaN) {
  return {name, false, log_scale, lower, upper, probe_fraction};
}

Effect encoder_offset_effect();
Effect encoder_scale_effect();
Effect sensor_delay_effect();
Effect coulomb_friction_effect();
Effect viscous_friction_effect();
Effect stribeck_effect();
Effect load_friction_effect();
Effect backlash_effect();
Effect joint_compliance_effect();
Effect link_flexibility_effect();
Effect resistance_drift_effect();
Effect supply_sag_effect();
Effect ground_compliance_effect();
Effect foot_slip_effect();
Effect directional_load_friction_effect();
Effect load_stribeck_friction_effect();
Effect quadratic_load_friction_effect();
Effect armature_effect();
Effect current_limit_effect();
Effect backdrive_friction_effect();
Effect mounting_offset_effect();
Effect winding_heating_effect();
Effect torque_saturation_effect();
Effect housing_temperature_effect();
Effect servo_derivative_effect();
Effect released_friction_effect();

}  // namespace motoflex::detail
