#include "motoflex/core/error.hpp"
#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex {
namespace {

void fill(const ExportInput& input, std::size_t actuator, const ParameterReader& get,
          ActuatorExport& a) {
  const ActuatorSpec& spec = input.model.actuators[actuator];
  const std::string gear = "gear." + spec.group + ".";
  const double ratio = get(gear + "ratio");
  const double resistance_ohm = get("motor.R_ohm");
  if (!(resistance_ohm > 0.0)) throw ModelError("motor.R_ohm must be positive");
  const double volts_to_torque =
      ratio * get("motor.stiffness") * get("motor.Kt_nm_per_a") / resistance_ohm;
  a.kp_nm_per_rad = volts_to_torque * get("pid.kp_v_per_rad");
  a.kv_nm_s_per_rad = volts_to_torque * get("pid.kd_v_s_per_rad");
  a.effort_nm = volts_to_torque * get("motor.supply_v");
  // B·ω_m reaches the joint as B·σ²·θ̇ (the rollout's implicit damper row).
  const double back_emf_damping = get(gear + "motor_viscous_nm_s_per_rad") * ratio * ratio;
  const std::string joint = "joint." + spec.name + ".";
  a.damping_nm_s_per_rad = get(joint + "viscous_nm_s_per_rad") + back_emf_damping;
  a.friction_nm = get(joint + "friction_nm");
  a.reduction = ratio;
  // The gear's small mass and the rotor's reflected inertia both act as joint-side inertia.
  a.armature = get(gear + "mass_kg_m2") + get(armature_parameter_name(spec));
}

}  // namespace

ServoExportRule motoflex_servo_export_rule() {
  return {"motoflex", "motoflex: PID -> DC motor -> gear with backlash (seed 001)", fill};
}

}  // namespace motoflex
