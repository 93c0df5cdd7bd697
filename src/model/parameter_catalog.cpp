#include "parameter_catalog.hpp"

namespace motoflex::detail {

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

}  // namespace motoflex::detail
