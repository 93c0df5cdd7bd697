#include "motoflex/sim/actuator/servo_stages.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/model/joint_units.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/torque_saturation.hpp"

namespace motoflex {

MotorCommand velocity_servo(const VelocityServoParams& params, double commanded_rad,
                            double measured_rad) {
  // Seed 000 §II-C, eq. 3; the torque limit is left to ODE's motor row, which clips the
  // force it applies to reach the velocity at fmax.
  return MotorCommand{-params.gain_per_s * (measured_rad - commanded_rad), params.torque_max_nm};
}

MotorCommand ideal_servo(const IdealServoParams& params, double next_commanded_rad,
                         double measured_rad, double dt_s) {
  if (!(dt_s > 0.0)) throw std::invalid_argument("ideal_servo: dt_s must be > 0");
  return MotorCommand{(next_commanded_rad - measured_rad) / dt_s, params.torque_max_nm};
}

BenchServoOutput bench_servo_output(const BenchServoParams& params, double commanded_rad,
                                    double measured_rad, double velocity_rad_s, bool torque_enabled,
                                    double command_rate_rad_s) {
  // A released H-bridge leaves the windings open: no current, so neither drive nor back-EMF
  // braking.
  if (!torque_enabled) return {};
  // BAM eq. 12: the firmware's P law saturates at the PWM duty limit. min/max rather than
  // std::clamp, which is undefined for a (bad) negative max_duty. A PD firmware adds T_d·ė
  // inside the same gain (skipped at T_d = 0, so the P law stays bit for bit).
  double error_rad = commanded_rad - measured_rad;
  if (params.derivative_s != 0.0) {
    error_rad += params.derivative_s * (command_rate_rad_s - velocity_rad_s);
  }
  const double duty = std::min(
      std::max(params.error_gain * params.kp * error_rad, -params.max_duty), params.max_duty);
  const double voltage_v = params.supply_v * duty;
  // BAM eq. 13: current (U − K_t·θ̇)/R through the windings, torque K_t·I.
  const double kt = params.torque_constant_nm_per_a;
  const double current_a = (voltage_v - kt * velocity_rad_s) / params.resistance_ohm;
  BenchServoOutput out;
  if (std::abs(current_a) > params.current_limit_a) {
    // The driver's current limit: at I_max the torque no longer follows the duty.
    out.current_a = std::copysign(params.current_limit_a, current_a);
    out.torque_nm = kt * saturated_current_a(out.current_a, params.saturation_per_a);
  } else if (params.saturation_per_a > 0.0) {
    out.current_a = current_a;
    out.torque_nm = kt * saturated_current_a(current_a, params.saturation_per_a);
  } else {
    // The linear motor in BAM's form, and the current as τ/K_t, as the law always computed them.
    out.torque_nm =
        kt * voltage_v / params.resistance_ohm - kt * kt * velocity_rad_s / params.resistance_ohm;
    out.current_a = out.torque_nm / kt;
  }
  return out;
}

double bench_servo_torque_nm(const BenchServoParams& params, double commanded_rad,
                             double measured_rad, double velocity_rad_s, bool torque_enabled) {
  return bench_servo_output(params, commanded_rad, measured_rad, velocity_rad_s, torque_enabled)
      .torque_nm;
}

double read_torque_saturation_per_a(const ParameterReader& get) {
  const double saturation_per_a = get("motor.torque_saturation_per_a");
  if (!(saturation_per_a >= 0.0)) {
    throw ModelError("motor.torque_saturation_per_a must not be negative");
  }
  return saturation_per_a;
}

std::string servo_parameter_prefix(const ActuatorSpec& actuator) {
  return "servo." + (actuator.servo_scope.empty() ? actuator.name : actuator.servo_scope) + ".";
}

double clip_torque_speed_nm(double torque_nm, double velocity_rad_s, double torque_max_nm,
                            double no_load_speed_rad_s) {
  double upper_nm = torque_max_nm;
  double lower_nm = -torque_max_nm;
  if (no_load_speed_rad_s > 0.0) {
    const double slope = velocity_rad_s / no_load_speed_rad_s;
    upper_nm = std::min(torque_max_nm, std::max(0.0, torque_max_nm * (1.0 - slope)));
    lower_nm = std::max(-torque_max_nm, std::min(0.0, torque_max_nm * (-1.0 - slope)));
  }
  // min/max rather than std::clamp, which is undefined for a (bad) lower > upper.
  return std::min(std::max(torque_nm, lower_nm), upper_nm);
}

std::vector<std::string> motoflex_pipeline_parameter_names(const ActuatorSpec& actuator) {
  static const char* const kMotorNames[] = {
      "pid.kp_v_per_rad", "pid.ki_v_per_rad_s", "pid.kd_v_s_per_rad", "motor.supply_v",
      "motor.R_ohm",      "motor.L_h",          "motor.Kt_nm_per_a",  "motor.stiffness"};
  static const char* const kGearLeaves[] = {"ratio",        "motor_viscous_nm_s_per_rad",
                                            "backlash_rad", "spring_nm_per_rad",
                                            "mass_kg_m2",   "viscous_nm_s_per_rad"};
  std::vector<std::string> out(std::begin(kMotorNames), std::end(kMotorNames));
  for (const char* leaf : kGearLeaves) out.push_back("gear." + actuator.group + "." + leaf);
  for (auto& name : friction_parameter_names(actuator.name, FrictionTerms::kMotorLoad)) {
    out.push_back(std::move(name));
  }
  return out;
}

std::string armature_parameter_name(const ActuatorSpec& actuator) {
  return joint_parameter(actuator, "armature", joint_units(actuator).inertia);
}

std::vector<std::string> scoped_law_parameter_names(const ActuatorSpec& actuator,
                                                    const std::vector<std::string>& leaves) {
  const std::string prefix = servo_parameter_prefix(actuator);
  std::vector<std::string> out;
  for (const std::string& leaf : leaves) out.push_back(prefix + leaf);
  for (auto& name : friction_parameter_names(actuator.name, FrictionTerms::kFamily)) {
    out.push_back(std::move(name));
  }
  out.push_back(armature_parameter_name(actuator));
  return out;
}

double read_armature(const ParameterReader& get, const ActuatorSpec& actuator) {
  const std::string name = armature_parameter_name(actuator);
  const double armature = get(name);
  if (armature < 0.0) throw ModelError(name + " must be >= 0");
  return armature;
}

namespace {

double finite_or(double value, double fallback) {
  return std::isfinite(value) && value >= 0.0 ? value : fallback;
}

}  // namespace

std::vector<ParameterDefault> joint_friction_defaults(const ActuatorSpec& joint,
                                                      const JointHints& hints) {
  const JointUnits u = joint_units(joint);
  const double effort_share = std::isfinite(hints.effort) ? 0.5 * hints.effort : 0.0;
  const auto entry = [&](const std::string& name, double hint, const char* what) {
    const double start = finite_or(hint, 0.0);
    const double upper = std::max({1.0, effort_share, 5.0 * start});
    return ParameterDefault{name, start, 0.0, upper,
                            std::isfinite(hint) && hint >= 0.0
                                ? std::string("URDF <dynamics ") + what + ">"
                                : std::string("none in the URDF: 0, up to max(1, effort/2)")};
  };
  return {entry(joint_parameter(joint, "friction", u.effort), hints.friction, "friction"),
          entry(joint_parameter(joint, "viscous", u.damping), hints.damping, "damping")};
}

}  // namespace motoflex
