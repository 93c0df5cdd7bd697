#include <numbers>

#include "motoflex/core/error.hpp"
#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

// The dynamixel and feetech laws linearised (firmware_servo_law.hpp): in the unsaturated region
// the joint torque is g·U_s·duty − g·K_t·N·θ̇ with g = N·K_t/R, and the firmware's duty is
// (kp/kp_div·e + kd/kd_div·Δe per 1 ms)·ticks_per_rad/pwm_full_scale, so
//   kp_joint = g·U_s·kp/kp_div·ticks_per_rad/full,  kv_joint = g·U_s·kd/kd_div·1
//   ms·ticks_per_rad/full, effort = g·U_s·pwm_limit/full,  damping = joint viscous + N²·K_t²/R
//   (back-EMF, outside the
// force limit as in BAM and the bench export). Dropped: the I term, integer ticks, the dead band,
// the current limit, the torque saturation, the load-dependent friction terms.
void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const ActuatorSpec& spec = input.model.actuators[actuator];
  const std::string prefix = servo_parameter_prefix(spec);
  const double resistance_ohm = get(prefix + "R_ohm");
  const double full_scale = get(prefix + "pwm_full_scale");
  if (!(resistance_ohm > 0.0) || !(full_scale > 0.0) || !(get(prefix + "kp_divisor") > 0.0) ||
      !(get(prefix + "kd_divisor") > 0.0)) {
    throw ModelError(prefix + "R_ohm, pwm_full_scale and the divisors must be positive");
  }
  const double ratio = get(prefix + "gear_ratio");
  const double kt = get(prefix + "Kt_nm_per_a");
  const double volts_to_torque = ratio * kt / resistance_ohm;
  const double counts_to_torque = volts_to_torque * get(prefix + "supply_v") / full_scale;
  const double ticks_per_rad = get(prefix + "ticks_per_rev") / (2.0 * std::numbers::pi);
  constexpr double kFirmwareCycle_s = 1e-3;
  a.kp_nm_per_rad =
      counts_to_torque * get(prefix + "kp") / get(prefix + "kp_divisor") * ticks_per_rad;
  a.kv_nm_s_per_rad = counts_to_torque * get(prefix + "kd") / get(prefix + "kd_divisor") *
                      kFirmwareCycle_s * ticks_per_rad;
  a.effort_nm = counts_to_torque * get(prefix + "pwm_limit");
  const std::string joint = "joint." + spec.name + ".";
  a.damping_nm_s_per_rad = get(joint + "viscous_nm_s_per_rad") + volts_to_torque * kt * ratio;
  a.friction_nm = get(joint + "friction_nm");
  a.reduction = ratio;
  a.armature = get(armature_parameter_name(spec));
}

}  // namespace

ServoExportRule dynamixel_servo_export_rule() {
  return {"dynamixel", "dynamixel: position firmware (P(I)D in ticks -> PWM -> DC motor)", fill};
}

ServoExportRule feetech_servo_export_rule() {
  return {"feetech", "feetech: position firmware (P(I)D in ticks -> PWM -> DC motor)", fill};
}

}  // namespace motoflex
