#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "stiff_servo.hpp"

namespace motoflex {
namespace {

void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const std::string joint = "joint." + input.model.actuators[actuator].name + ".";
  a.armature_kg_m2 = get(armature_parameter_name(input.model.actuators[actuator].name));
  a.kv_nm_s_per_rad = detail::stiff_servo_kv_nm_s_per_rad(input, actuator, a.armature_kg_m2);
  a.kp_nm_per_rad = a.kv_nm_s_per_rad * get(joint + "gain_per_s");
  a.effort_nm = get(joint + "torque_max_nm");
  // The law applies the joint's Coulomb + viscous friction beside the servo row.
  a.damping_nm_s_per_rad = get(joint + "viscous_nm_s_per_rad");
  a.friction_nm = get(joint + "friction_nm");
}

}  // namespace

ServoExportRule velocity_servo_export_rule() {
  return {"velocity", "velocity: velocity servo with a torque limit (seed 000)", fill};
}

}  // namespace motoflex
