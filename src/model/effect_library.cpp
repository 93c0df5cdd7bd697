#include "motoflex/model/effect_library.hpp"

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

EffectParameter per_joint(const std::string& leaf, double probe_fraction, bool log_scale = false,
                          double lower = kNaN, double upper = kNaN) {
  return {"joint.*." + leaf, true, log_scale, lower, upper, probe_fraction};
}

EffectParameter global(const std::string& name, double probe_fraction, bool log_scale = false,
                       double lower = kNaN, double upper = kNaN) {
  return {name, false, log_scale, lower, upper, probe_fraction};
}

std::vector<Effect> build_library() {
  std::vector<Effect> effects;
  effects.push_back({"encoder_offset",
                     "a constant offset of each joint's encoder (calibration error)",
                     "a constant per joint, whatever the motion",
                     {per_joint("encoder_offset_rad", 0.05)},
                     false,
                     0});
  effects.push_back({"encoder_scale",
                     "an encoder or gear-ratio scale error of each joint",
                     "proportional to the joint angle",
                     {per_joint("encoder_scale", 0.05)},
                     false,
                     0});
  effects.push_back({"sensor_delay",
                     "the logged angles lag the joint by a transport delay",
                     "minus the joint velocity times the delay; the cross-correlation of "
                     "measured and simulated angles peaks at a positive lag",
                     {global("sensor.delay_s", 0.05)},
                     false,
                     0});
  effects.push_back({"coulomb_friction",
                     "velocity-independent dry friction in each joint",
                     "a step with the sign of the joint velocity",
                     {per_joint("friction_nm", 0.05)},
                     false,
                     0});
  effects.push_back({"viscous_friction",
                     "friction proportional to the joint velocity",
                     "proportional to the joint velocity, filtered by the servo loop",
                     {per_joint("viscous_nm_s_per_rad", 0.05)},
                     false,
                     0});
  effects.push_back(
      {"stribeck",
       "stiction: extra breakaway friction at low joint speed",
       "large near velocity reversals and standstill, vanishing at speed",
       {per_joint("stribeck_nm", 0.05), per_joint("stribeck_velocity_rad_s", 0.0, true)},
       false,
       0});
  effects.push_back({"load_friction",
                     "friction growing with the transmitted torque (BAM's M3-M6 family)",
                     "a step with the sign of the joint velocity, scaled by the load torque",
                     {per_joint("load_friction", 0.05)},
                     false,
                     0});
  effects.push_back({"backlash",
                     "play in the gear train",
                     "a dead band at every reversal of the load torque",
                     {{"gear.*.backlash_rad", true, true, 1.0e-6, 0.05, 0.5}},
                     false,
                     0});
  effects.push_back({"joint_compliance",
                     "elasticity of the gear train",
                     "proportional to the load torque, with a resonance of the servo loop",
                     {{"gear.*.spring_nm_per_rad", true, true, kNaN, kNaN, -0.3}},
                     false,
                     0});
  effects.push_back({"link_flexibility",
                     "bending of thighs and tibias (sub-bodies and springs)",
                     "oscillations under load and a load-dependent offset of the legs",
                     {global("flex.spring_nm_per_rad", -0.3, true),
                      global("flex.damping_nm_s_per_rad", 0.0, true)},
                     false,
                     2});
  effects.push_back({"resistance_drift",
                     "motor resistance rising over the run (winding heat)",
                     "a servo error that grows with time and with the load",
                     {global("motor.R_drift_per_s", 0.05)},
                     false,
                     0});
  effects.push_back({"supply_sag",
                     "battery voltage falling with the total motor current",
                     "weaker servos when many joints draw current at once",
                     {global("motor.supply_sag_ohm", 0.05)},
                     false,
                     0});
  effects.push_back({"ground_compliance",
                     "softer ground contact (contact ERP/CFM)",
                     "sinking and rebound of the stance leg at every touchdown",
                     {global("contact.soft_cfm", 0.2, true), global("contact.soft_erp", 0.0)},
                     true,
                     0});
  effects.push_back({"foot_slip",
                     "feet sliding on the ground (contact slip and friction)",
                     "drift of the stance leg angles during single support",
                     {global("contact.slip", 0.2, true), global("contact.mu", 0.0)},
                     true,
                     0});
  // Appended after the effects above, so that their order (and the loop's ties) stays.
  // BAM's directional and quadratic friction (M4–M6, bam.md §2d) on the laws that read the whole
  // family (pd_torque, dynamixel, feetech; friction_family.hpp). The coefficients above are M1–M3.
  effects.push_back({"directional_load_friction",
                     "friction growing with the external (gravity) torque apart from the motor's "
                     "(BAM's M5)",
                     "a step with the sign of the joint velocity, scaled by the gravity load",
                     {per_joint("load_friction_external", 0.05)},
                     false,
                     0});
  effects.push_back({"load_stribeck_friction",
                     "load-dependent stiction: breakaway friction growing with the load (BAM's "
                     "M4/M5)",
                     "large at reversals and standstill under load, vanishing at speed",
                     {per_joint("load_friction_stribeck", 0.05),
                      per_joint("load_friction_external_stribeck", 0.05)},
                     false,
                     0});
  effects.push_back({"quadratic_load_friction",
                     "stiction growing with the square of the load when motor and gravity oppose "
                     "(BAM's M6)",
                     "at low speed while the motor holds or lowers a load",
                     {per_joint("load_friction_quad_per_nm", 0.05),
                      per_joint("load_friction_external_quad_per_nm", 0.05)},
                     false,
                     0});
  effects.push_back({"armature",
                     "rotor inertia reflected through the gear (armature) on each joint",
                     "proportional to the joint acceleration: lag and overshoot growing with the "
                     "command's frequency",
                     {per_joint("armature_kg_m2", 0.05)},
                     false,
                     0});
  return effects;
}

}  // namespace

const std::vector<Effect>& effect_library() {
  static const std::vector<Effect> library = build_library();
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
