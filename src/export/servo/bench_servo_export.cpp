#include "motoflex/core/error.hpp"
#include "motoflex/export/servo_export.hpp"

namespace motoflex {
namespace {

void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const double resistance_ohm = get("bench.R_ohm");
  if (!(resistance_ohm > 0.0)) throw ModelError("bench.R_ohm must be positive");
  const double kt = get("bench.Kt_nm_per_a");
  const double supply_v = get("bench.supply_v");
  const double volts_to_torque = kt / resistance_ohm;
  a.kp_nm_per_rad = volts_to_torque * supply_v * get("bench.error_gain") * get("bench.kp");
  // A PD firmware's D, duty g·kp·T_d·ė: its joint-rate part is the actuator's kv (inside the
  // force limit, like the firmware laws' kd); the goal-rate part has no counterpart (the export's
  // control input is the goal alone) and is dropped.
  a.kv_nm_s_per_rad = a.kp_nm_per_rad * get("bench.derivative_s");
  // Dropped (no MuJoCo counterpart): the current limit, the torque saturation, the winding's
  // heating and the load-dependent friction terms.
  a.effort_nm = volts_to_torque * supply_v * get("bench.max_duty");
  const std::string joint = "joint." + input.model.actuators[actuator].name + ".";
  // BAM eq. 13's back-EMF term K_t²/R is joint damping (outside the force limit).
  a.damping_nm_s_per_rad = get(joint + "viscous_nm_s_per_rad") + kt * volts_to_torque;
  a.friction_nm = get(joint + "friction_nm");
  a.armature = get("bench.armature_kg_m2");
}

}  // namespace

ServoExportRule bench_servo_export_rule() {
  return {"bench", "bench: voltage P servo of the pendulum bench (BAM)", fill};
}

}  // namespace motoflex
