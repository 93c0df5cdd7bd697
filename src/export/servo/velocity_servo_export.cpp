#include "motoflex/export/servo_export.hpp"
#include "stiff_servo.hpp"

namespace motoflex {
namespace {

void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const ActuatorSpec& spec = input.model.actuators[actuator];
  const std::string joint = "joint." + spec.name + ".";
  a.kv_nm_s_per_rad = detail::stiff_servo_kv_nm_s_per_rad(input, actuator);
  a.kp_nm_per_rad = a.kv_nm_s_per_rad * get(joint + "gain_per_s");
  a.effort_nm = get(joint + (spec.prismatic ? "force_max_n" : "torque_max_nm"));  // N on a slider
}

}  // namespace

ServoExportRule velocity_servo_export_rule() {
  return {"velocity", "velocity: velocity servo with a torque limit (seed 000)", fill};
}

}  // namespace motoflex
