#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "stiff_servo.hpp"

namespace motoflex {
namespace {

void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  a.armature = get(armature_parameter_name(input.model.actuators[actuator]));
  a.kv_nm_s_per_rad = detail::stiff_servo_kv_nm_s_per_rad(input, actuator, a.armature);
  a.kp_nm_per_rad = a.kv_nm_s_per_rad / input.dt_s;
  a.effort_nm =
      get(input.model.actuators[actuator].prismatic ? "ideal.force_max_n" : "ideal.torque_max_nm");
}

}  // namespace

ServoExportRule ideal_servo_export_rule() {
  ServoExportRule rule{"ideal",
                       "ideal: reaches the next commanded angle in one step, torque limited", fill};
  rule.command_is_next_angle = true;
  return rule;
}

}  // namespace motoflex
