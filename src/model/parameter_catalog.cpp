#include "parameter_catalog.hpp"

namespace motoflex::detail {
namespace {

const std::vector<std::string> kPidMotor = {
    "pid.kp_v_per_rad", "pid.ki_v_per_rad_s", "pid.kd_v_s_per_rad", "motor.supply_v",
    "motor.R_ohm",      "motor.L_h",          "motor.Kt_nm_per_a",  "motor.stiffness"};
const std::vector<std::string> kGearLeaves = {"ratio",        "motor_viscous_nm_s_per_rad",
                                              "backlash_rad", "spring_nm_per_rad",
                                              "mass_kg_m2",   "viscous_nm_s_per_rad"};
const std::vector<std::string> kBench = {
    "bench.kp",          "bench.error_gain",  "bench.max_duty",       "bench.supply_v",
    "bench.Kt_nm_per_a", "bench.R_ohm",       "bench.armature_kg_m2", "bench.mass_kg",
    "bench.length_m",    "bench.torque_off_s"};
const std::vector<std::string> kCommon = {
    "contact.mu", "contact.soft_erp",       "contact.soft_cfm", "contact.slip",  "world.erp",
    "world.cfm",  "sensor.resolution_bits", "sensor.noise_rad", "sensor.delay_s"};
const std::vector<std::string> kFlex = {"flex.spring_nm_per_rad", "flex.damping_nm_s_per_rad",
                                        "flex.friction_nm"};

std::vector<std::string> groups_of(const RobotModel& model) {
  std::vector<std::string> groups;
  for (const auto& a : model.actuators) {
    bool seen = false;
    for (const auto& g : groups) seen = seen || g == a.group;
    if (!seen) groups.push_back(a.group);
  }
  return groups;
}

bool has_flex_joints(const RobotModel& model) {
  for (const auto& j : model.joints) {
    if (j.kind == JointKind::kFlex) return true;
  }
  return false;
}

void append(std::vector<std::string>& out, const std::vector<std::string>& more) {
  out.insert(out.end(), more.begin(), more.end());
}

}  // namespace

std::vector<ParameterSpec> effect_parameter_specs(const RobotModel& model) {
  std::vector<ParameterSpec> specs;
  auto add = [&specs](const std::string& name, double neutral, double lower, double upper) {
    specs.push_back({name, unit_from_parameter_name(name), neutral, lower, upper});
  };
  for (const auto& a : model.actuators) {
    const std::string joint = "joint." + a.name + ".";
    add(joint + "friction_nm", 0.0, 0.0, 5.0);
    add(joint + "viscous_nm_s_per_rad", 0.0, 0.0, 5.0);
    add(joint + "encoder_offset_rad", 0.0, -0.1, 0.1);
    add(joint + "encoder_scale", 1.0, 0.9, 1.1);
    add(joint + "stribeck_nm", 0.0, 0.0, 2.0);
    add(joint + "stribeck_velocity_rad_s", 0.1, 0.005, 2.0);
    add(joint + "load_friction", 0.0, 0.0, 0.5);
  }
  add("motor.R_drift_per_s", 0.0, -0.01, 0.05);
  add("motor.supply_sag_ohm", 0.0, 0.0, 5.0);
  add("sensor.resolution_bits", 0.0, 0.0, 24.0);
  add("sensor.noise_rad", 0.0, 0.0, 0.05);
  add("sensor.delay_s", 0.0, 0.0, 0.1);
  return specs;
}

std::set<std::string> known_parameter_names(const RobotModel& model) {
  std::set<std::string> names(kPidMotor.begin(), kPidMotor.end());
  names.insert(kBench.begin(), kBench.end());
  names.insert(kCommon.begin(), kCommon.end());
  names.insert(kFlex.begin(), kFlex.end());
  names.insert("ideal.torque_max_nm");
  for (const auto& spec : effect_parameter_specs(model)) names.insert(spec.name);
  for (const auto& group : groups_of(model)) {
    for (const auto& leaf : kGearLeaves) names.insert("gear." + group + "." + leaf);
  }
  for (const auto& a : model.actuators) {
    for (const char* leaf :
         {"friction_nm", "viscous_nm_s_per_rad", "gain_per_s", "torque_max_nm"}) {
      names.insert("joint." + a.name + "." + leaf);
    }
  }
  return names;
}

std::vector<std::string> required_parameter_names(const RobotModel& model, ServoKind servo) {
  std::vector<std::string> names;
  switch (servo) {
    case ServoKind::kMotoflex:
      append(names, kPidMotor);
      for (const auto& group : groups_of(model)) {
        for (const auto& leaf : kGearLeaves) names.push_back("gear." + group + "." + leaf);
      }
      for (const auto& a : model.actuators) {
        names.push_back("joint." + a.name + ".friction_nm");
        names.push_back("joint." + a.name + ".viscous_nm_s_per_rad");
      }
      break;
    case ServoKind::kVelocity:
      for (const auto& a : model.actuators) {
        names.push_back("joint." + a.name + ".gain_per_s");
        names.push_back("joint." + a.name + ".torque_max_nm");
      }
      break;
    case ServoKind::kIdeal:
      names.push_back("ideal.torque_max_nm");
      break;
    case ServoKind::kBench:
      append(names, kBench);
      for (const auto& a : model.actuators) {
        names.push_back("joint." + a.name + ".friction_nm");
        names.push_back("joint." + a.name + ".viscous_nm_s_per_rad");
      }
      break;
  }
  append(names, kCommon);
  if (has_flex_joints(model)) append(names, kFlex);
  return names;
}

}  // namespace motoflex::detail
