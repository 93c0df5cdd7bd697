#include "motoflex/sim/actuator/servo_stages.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/model/joint_units.hpp"

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

double bench_servo_torque_nm(const BenchServoParams& params, double commanded_rad,
                             double measured_rad, double velocity_rad_s, bool torque_enabled) {
  // A released H-bridge leaves the windings open: no current, so neither drive nor back-EMF
  // braking.
  if (!torque_enabled) return 0.0;
  // BAM eq. 12: the firmware's P law saturates at the PWM duty limit. min/max rather than
  // std::clamp, which is undefined for a (bad) negative max_duty.
  const double duty = std::min(
      std::max(params.error_gain * params.kp * (commanded_rad - measured_rad), -params.max_duty),
      params.max_duty);
  const double voltage_v = params.supply_v * duty;
  // BAM eq. 13: current (U − K_t·θ̇)/R through the windings, torque K_t·I.
  const double kt = params.torque_constant_nm_per_a;
  return kt * voltage_v / params.resistance_ohm - kt * kt * velocity_rad_s / params.resistance_ohm;
}

MotorCommand joint_friction(const JointFrictionParams& params, double velocity_rad_s,
                            double load_torque_nm) {
  // A zero-velocity motor row with a bounded force is ODE's way to express stiction: the joint
  // is held while the holding torque fits in the budget, and slides once it does not.
  double budget_nm = params.coulomb_nm + params.viscous_nm_s_per_rad * std::abs(velocity_rad_s);
  if (params.stribeck_nm != 0.0) {
    const double u = velocity_rad_s / params.stribeck_velocity_rad_s;
    budget_nm += params.stribeck_nm * std::exp(-u * u);
  }
  budget_nm += params.load_coefficient * std::abs(load_torque_nm);
  return MotorCommand{0.0, budget_nm};
}

namespace {

JointFrictionParams read_friction_names(const ParameterReader& get,
                                        const std::vector<std::string>& names,
                                        const std::string& prefix) {
  JointFrictionParams friction;
  friction.coulomb_nm = get(names[0]);
  friction.viscous_nm_s_per_rad = get(names[1]);
  friction.stribeck_nm = get(names[2]);
  friction.stribeck_velocity_rad_s = get(names[3]);
  friction.load_coefficient = get(names[4]);
  if (friction.coulomb_nm < 0.0 || friction.viscous_nm_s_per_rad < 0.0 ||
      friction.stribeck_nm < 0.0 || !(friction.stribeck_velocity_rad_s > 0.0) ||
      friction.load_coefficient < 0.0) {
    throw ModelError("friction parameters of " + prefix + "* must not be negative (" + names[3] +
                     " > 0)");
  }
  return friction;
}

double finite_or(double value, double fallback) {
  return std::isfinite(value) && value >= 0.0 ? value : fallback;
}

}  // namespace

JointFrictionParams read_joint_friction(const ParameterReader& get, const std::string& joint) {
  return read_friction_names(get, joint_friction_parameter_names(joint), "joint." + joint + ".");
}

JointFrictionParams read_joint_friction(const ParameterReader& get, const ActuatorSpec& joint) {
  return read_friction_names(get, joint_friction_parameter_names(joint),
                             "joint." + joint.name + ".");
}

std::vector<std::string> joint_friction_parameter_names(const ActuatorSpec& joint) {
  const JointUnits u = joint_units(joint);
  return {joint_parameter(joint, "friction", u.effort),
          joint_parameter(joint, "viscous", u.damping),
          joint_parameter(joint, "stribeck", u.effort),
          joint_parameter(joint, "stribeck_velocity", u.velocity),
          "joint." + joint.name + ".load_friction"};
}

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

std::vector<std::string> joint_friction_parameter_names(const std::string& joint) {
  const std::string prefix = "joint." + joint + ".";
  return {prefix + "friction_nm", prefix + "viscous_nm_s_per_rad", prefix + "stribeck_nm",
          prefix + "stribeck_velocity_rad_s", prefix + "load_friction"};
}

}  // namespace motoflex
