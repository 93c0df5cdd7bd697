#include "parameter_catalog.hpp"

#include <cmath>
#include <limits>

#include "motoflex/model/joint_units.hpp"
#include "motoflex/model/parameter_domain.hpp"
#include "motoflex/model/torque_terms.hpp"

namespace motoflex::detail {

namespace {

void add_spec(std::vector<ParameterSpec>& specs, const std::string& name, double neutral,
              double lower, double upper) {
  specs.push_back({name, unit_from_parameter_name(name), neutral, lower, upper});
}

// add(name, neutral, lower, upper) appending to `specs`.
auto spec_adder(std::vector<ParameterSpec>& specs) {
  return [&specs](const std::string& name, double neutral, double lower, double upper) {
    add_spec(specs, name, neutral, lower, upper);
  };
}

// The per-joint effects appended after the robot-wide current limit, in this order.
void append_joint_effect_specs(std::vector<ParameterSpec>& specs, const RobotModel& model) {
  const auto add = spec_adder(specs);
  // Appended: the gear's back-driving loss (friction_family.hpp, the effect backdrive_friction),
  // per N·m of load torque; 1 would hold any load at standstill.
  for (const auto& a : model.actuators) {
    const std::string joint = "joint." + a.name + ".";
    add(joint + "backdrive_friction", 0.0, 0.0, 1.0);
    add(joint + "backdrive_friction_static", 0.0, 0.0, 1.0);
  }
  // Appended: the encoder's zero against the load's (the effect mounting_offset; BAM's q_offset
  // bounds, ±0.1 rad).
  for (const auto& a : model.actuators) {
    add(joint_parameter(a, "mounting_offset", joint_units(a).position), 0.0, -0.1, 0.1);
  }
  // Appended: a released joint's friction against the powered one's (released_friction.hpp, the
  // effect released_friction); 0 is the powered friction. ±0.2 spans a small servo's Coulomb
  // level and its viscous coefficient several times over.
  for (const auto& a : model.actuators) {
    const JointUnits units = joint_units(a);
    add(joint_parameter(a, "released_friction_delta", units.effort), 0.0, -0.2, 0.2);
    add(joint_parameter(a, "released_viscous_delta", units.damping), 0.0, -0.2, 0.2);
  }
}

// The robot-wide motor effects appended last (after every per-joint block above them).
void append_servo_effect_specs(std::vector<ParameterSpec>& specs) {
  const auto add = spec_adder(specs);
  // The winding's Joule heating (the effect winding_heating; winding_heating.hpp): no heating at
  // R_th = 0; C a small servo's winding, about a gram of copper.
  add("motor.winding_k_per_w", 0.0, 0.0, 200.0);
  add("motor.winding_heat_j_per_k", 0.5, 0.01, 20.0);
  // The motor's torque saturation k = 1/I_s (the effect torque_saturation;
  // torque_saturation.hpp): linear at 0; 5 /A saturates at 0.2 A, below a small servo's stall.
  add("motor.torque_saturation_per_a", 0.0, 0.0, 5.0);
  // The servo's housing temperature (°C; a log's own reading, e.g. the BAM import's median
  // temp) and the winding resistance's change per kelvin of it (the effect housing_temperature:
  // R = R_25·(1 + α·(T − 25 °C)); copper 0.00393 /K; 0 = off, the temperature then unused).
  // Its neutral is the reference temperature itself (winding_heating.hpp's kResistanceReferenceC).
  add("motor.housing_temperature_c", 25.0, -40.0, 150.0);
  add("motor.R_temperature_per_k", 0.0, 0.0, 0.05);
  // The bench firmware's derivative time T_d (s; the effect servo_derivative): duty =
  // g·kp·(e + T_d·ė). 0 = the P law BAM describes; 50 ms is far beyond any servo's D.
  add("bench.derivative_s", 0.0, 0.0, 0.05);
}

}  // namespace

std::vector<ParameterSpec> effect_parameter_specs(const RobotModel& model) {
  std::vector<ParameterSpec> specs;
  const auto add = spec_adder(specs);
  for (const auto& a : model.actuators) {
    // A prismatic joint's names end in m and N (same numbers: these are neutral switches;
    // a robot that fits them declares its own bounds).
    const JointUnits u = joint_units(a);
    const std::string joint = "joint." + a.name + ".";
    add(joint_parameter(a, "friction", u.effort), 0.0, 0.0, 5.0);
    add(joint_parameter(a, "viscous", u.damping), 0.0, 0.0, 5.0);
    add(joint_parameter(a, "encoder_offset", u.position), 0.0, -0.1, 0.1);
    add(joint + "encoder_scale", 1.0, 0.9, 1.1);
    add(joint_parameter(a, "stribeck", u.effort), 0.0, 0.0, 2.0);
    add(joint_parameter(a, "stribeck_velocity", u.velocity), 0.1, 0.005, 2.0);
    add(joint + "load_friction", 0.0, 0.0, 0.5);
  }
  add("motor.R_drift_per_s", 0.0, -0.01, 0.05);
  add("motor.supply_sag_ohm", 0.0, 0.0, 5.0);
  add("sensor.resolution_bits", 0.0, 0.0, 24.0);
  add("sensor.noise_rad", 0.0, 0.0, 0.05);
  add("sensor.delay_s", 0.0, 0.0, 0.1);
  // Added after the others so that the names above keep their order in parameter files.
  for (const auto& a : model.actuators) {
    const std::string joint = "joint." + a.name + ".";
    // Reflected rotor inertia J_rotor·σ² about the joint axis (every law but bench, whose arm
    // carries bench.armature_kg_m2); MX-106 0.027, eRob80 up to 1.1 kg·m² (bam.md §2f). On a
    // slider it is a mass (joint.<J>.armature_kg: J_rotor·σ² with σ in rad/m).
    add(joint_parameter(a, "armature", joint_units(a).inertia), 0.0, 0.0, 0.1);
    // BAM's friction family (bam.md §2d; src/sim/actuator/friction_family.hpp). The exponent 2
    // is the Gaussian Stribeck curve of stribeck_nm; the model 6 is the most general, which
    // with these zero coefficients is Coulomb + viscous. Bounds: BAM's search bounds.
    add(joint + "stribeck_exponent", 2.0, 0.5, 10.0);
    add(joint + "load_friction_external", 0.0, 0.0, 0.5);
    add(joint + "load_friction_stribeck", 0.0, 0.0, 1.0);
    add(joint + "load_friction_external_stribeck", 0.0, 0.0, 1.0);
    // Per N·m of torque, or per N of force on a slider (friction_family.hpp).
    const std::string per = a.prismatic ? "_per_n" : "_per_nm";
    add(joint + "load_friction_quad" + per, 0.0, 0.0, 0.01);
    add(joint + "load_friction_external_quad" + per, 0.0, 0.0, 0.01);
    add(joint + "friction_model", 6.0, 1.0, 6.0);
  }
  // Appended: the loop's candidate torque terms and the hidden truths' extra torques
  // (torque_terms.hpp), all neutral.
  const TruthTorques truth;
  for (const auto& a : model.actuators) {
    for (const TorqueTerm& term : torque_terms()) {
      add(term_parameter(a.name, term.leaf), 0.0, -term.bound, term.bound);
    }
    const std::string joint = "joint." + a.name + ".";
    add(joint + "cogging_nm", truth.cogging_nm, 0.0, 1.0);
    add(joint + "cogging_periods", truth.cogging_periods, 1.0, 64.0);
    add(joint + "cogging_phase_rad", truth.cogging_phase_rad, -4.0, 4.0);
    add(joint + "drag_nm_s2_per_rad2", truth.drag_nm_s2_per_rad2, 0.0, 1.0);
    add(joint + "load_saturation_nm", truth.load_saturation_nm, 0.0, 2.0);
    add(joint + "load_saturation_scale_nm", truth.load_saturation_scale_nm, 0.01, 5.0);
  }
  // Appended: a driver's current limit (the bench's voltage servo; the effect current_limit):
  // 1e3 A never binds on a servo.
  add("motor.current_limit_a", 1.0e3, 0.05, 1.0e3);
  append_joint_effect_specs(specs, model);
  append_servo_effect_specs(specs);
  return specs;
}

}  // namespace motoflex::detail

namespace motoflex {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One rule of the catalog: names whose last dotted part is `leaf` (or, when `full` is set,
// the whole name) take `domain`. More specific rules come first.
struct DomainRule {
  const char* name;
  bool full;  // match the whole dotted name rather than its last part
  ParameterDomain domain;
};

constexpr ParameterDomain kPositive{0.0, kInf, true, false, false};
constexpr ParameterDomain kNonNegative{0.0, kInf, false, false, false};
constexpr ParameterDomain kUnitInterval{0.0, 1.0, false, false, false};

// Why each one: the model's own invariants (src/sim/actuator/*: GearTrain, DcMotor, the
// firmware, the friction family, the encoder), ODE's (CFM >= 0, ERP in [0, 1], mu >= 0).
const DomainRule kDomainRules[] = {
    {"flex.spring_nm_per_rad", true, kPositive},  // a link spring of 0 has no rest pose
    {"world.erp", true, kUnitInterval},
    {"world.cfm", true, kNonNegative},
    {"contact.soft_erp", true, kUnitInterval},
    {"contact.soft_cfm", true, kNonNegative},
    {"contact.mu", true, kNonNegative},
    {"contact.slip", true, kNonNegative},
    {"bench.max_duty", true, kUnitInterval},
    {"bench.logged_supply", true, {0.0, 1.0, false, false, true}},  // a switch: 0 or 1
    {"motor.R_temperature_per_k", true, kNonNegative},
    {"bench.derivative_s", true, kNonNegative},
    // The bench law's driver limit has no "off" value (its neutral is 1e3 A); the firmware laws'
    // servo.<S>.current_limit_a takes 0 for none (the generic rule below).
    {"motor.current_limit_a", true, kPositive},
    {"motor.winding_k_per_w", true, kNonNegative},
    {"motor.winding_heat_j_per_k", true, kPositive},
    {"motor.torque_saturation_per_a", true, kNonNegative},
    {"R_ohm", false, kPositive},
    {"L_h", false, kNonNegative},
    {"Kt_nm_per_a", false, kPositive},
    {"ratio", false, kPositive},
    {"gear_ratio", false, kPositive},
    {"mass_kg_m2", false, kPositive},
    {"mass_kg", false, kPositive},
    {"length_m", false, kPositive},
    {"backlash_rad", false, kNonNegative},
    {"spring_nm_per_rad", false, kNonNegative},
    {"viscous_nm_s_per_rad", false, kNonNegative},
    {"motor_viscous_nm_s_per_rad", false, kNonNegative},
    {"damping_nm_s_per_rad", false, kNonNegative},
    {"friction_nm", false, kNonNegative},
    {"stribeck_nm", false, kNonNegative},
    {"stribeck_velocity_rad_s", false, kPositive},
    {"stribeck_exponent", false, kPositive},
    {"load_friction", false, kNonNegative},
    {"load_friction_external", false, kNonNegative},
    {"load_friction_stribeck", false, kNonNegative},
    {"load_friction_external_stribeck", false, kNonNegative},
    {"load_friction_quad_per_nm", false, kNonNegative},
    {"load_friction_external_quad_per_nm", false, kNonNegative},
    {"friction_model", false, {1.0, 6.0, false, false, true}},  // BAM's M1-M6
    {"backdrive_friction", false, kNonNegative},
    {"backdrive_friction_static", false, kNonNegative},
    {"cogging_nm", false, kNonNegative},
    {"cogging_periods", false, kPositive},
    {"drag_nm_s2_per_rad2", false, kNonNegative},
    {"load_saturation_nm", false, kNonNegative},
    {"load_saturation_scale_nm", false, kPositive},
    {"resolution_bits", false, {0.0, 32.0, false, false, true}},
    {"noise_rad", false, kNonNegative},
    {"delay_s", false, kNonNegative},
    {"encoder_scale", false, kPositive},
    {"armature_kg_m2", false, kNonNegative},
    {"armature_kg", false, kNonNegative},  // a slider's reflected mass
    {"supply_v", false, kNonNegative},
    {"supply_sag_ohm", false, kNonNegative},
    {"current_limit_a", false, kNonNegative},
    {"torque_max_nm", false, kNonNegative},
    {"torque_off_s", false, kNonNegative},
    {"no_load_speed_rad_s", false, kNonNegative},  // 0: no torque–speed curve
    {"ticks_per_rev", false, {1.0, kInf, false, false, true}},
    {"pwm_full_scale", false, kPositive},
};

// Gains of a controller (kp, ki_v_per_rad_s, gain_per_s, kd_divisor, ...): never negative.
bool is_gain(const std::string& leaf) {
  for (const char* prefix : {"kp", "ki", "kd", "gain_per_s", "pwm_limit", "deadband"}) {
    if (leaf.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

}  // namespace

ParameterDomain parameter_domain(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::string leaf = dot == std::string::npos ? name : name.substr(dot + 1);
  for (const DomainRule& rule : kDomainRules) {
    if (rule.full ? name == rule.name : leaf == rule.name) return rule.domain;
  }
  if (leaf.find("_divisor") != std::string::npos) return kPositive;
  if (is_gain(leaf)) return kNonNegative;
  return {};
}

}  // namespace motoflex
