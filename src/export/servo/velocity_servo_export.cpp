#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "stiff_servo.hpp"

namespace motoflex {
namespace {

void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const ActuatorSpec& spec = input.model.actuators[actuator];
  const std::string joint = "joint." + spec.name + ".";
  a.armature = get(armature_parameter_name(spec));
  a.kv_nm_s_per_rad = detail::stiff_servo_kv_nm_s_per_rad(input, actuator, a.armature);
  a.kp_nm_per_rad = a.kv_nm_s_per_rad * get(joint + "gain_per_s");
  a.effort_nm = get(joint + (spec.prismatic ? "force_max_n" : "torque_max_nm"));  // N on a slider
  // The law applies the joint's Coulomb + viscous friction beside the servo row.
  const std::vector<std::string> friction =
      friction_parameter_names(spec, FrictionTerms::kSpeedOnly);
  a.friction_nm = get(friction[0]);
  a.damping_nm_s_per_rad = get(friction[1]);
}

}  // namespace

ServoExportRule velocity_servo_export_rule() {
  return {"velocity", "velocity: velocity servo with a torque limit (seed 000)", fill};
}

}  // namespace motoflex
