#include "motoflex/core/error.hpp"
#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

// pd_torque is already a linear PD with a force limit: kp, kv = kd, effort = τ_max. Its
// torque–speed curve becomes the joint's velocity limit (the no-load speed ω₀), which URDF and
// SDF carry and MuJoCo does not enforce; BAM's load-dependent friction terms are dropped.
void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const ActuatorSpec& spec = input.model.actuators[actuator];
  const std::string prefix = servo_parameter_prefix(spec);
  a.kp_nm_per_rad = get(prefix + "kp_nm_per_rad");
  a.kv_nm_s_per_rad = get(prefix + "kd_nm_s_per_rad");
  a.effort_nm = get(prefix + "torque_max_nm");
  a.velocity_rad_s = get(prefix + "no_load_speed_rad_s");
  const std::string joint = "joint." + spec.name + ".";
  a.damping_nm_s_per_rad = get(joint + "viscous_nm_s_per_rad");
  a.friction_nm = get(joint + "friction_nm");
  a.armature = get(armature_parameter_name(spec));
}

}  // namespace

ServoExportRule pd_torque_servo_export_rule() {
  return {"pd_torque", "pd_torque: torque PD with a force limit", fill};
}

}  // namespace motoflex
