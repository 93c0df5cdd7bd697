#include "parameter_catalog.hpp"

#include "motoflex/model/joint_units.hpp"

namespace motoflex::detail {

std::vector<ParameterSpec> effect_parameter_specs(const RobotModel& model) {
  std::vector<ParameterSpec> specs;
  auto add = [&specs](const std::string& name, double neutral, double lower, double upper) {
    specs.push_back({name, unit_from_parameter_name(name), neutral, lower, upper});
  };
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
    // carries bench.armature_kg_m2); MX-106 0.027, eRob80 up to 1.1 kg·m² (bam.md §2f).
    add(joint + "armature_kg_m2", 0.0, 0.0, 0.1);
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
  return specs;
}

}  // namespace motoflex::detail
