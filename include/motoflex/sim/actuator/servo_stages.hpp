#pragma once

// The stages the servo laws are made of, as pure functions of their inputs (the laws in
// src/sim/actuator/*_servo_law.cpp hold the state and read the parameters).

#include <string>
#include <vector>

#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

// Seed 000 §II-C, eq. 3: θ̇_d = −k_d(θ − θ_d), torque limited to τ_max (Table I).
struct VelocityServoParams {
  double gain_per_s = 4.0;      // k_d
  double torque_max_nm = 10.0;  // τ_max
};
MotorCommand velocity_servo(const VelocityServoParams& params, double commanded_rad,
                            double measured_rad);

// An ideal position servo: asks for the velocity that reaches the next commanded angle in one
// step, with a generous torque limit (used for "ideal servos" runs and as a reference).
// Throws std::invalid_argument if dt_s <= 0.
struct IdealServoParams {
  double torque_max_nm = 100.0;
};
MotorCommand ideal_servo(const IdealServoParams& params, double next_commanded_rad,
                         double measured_rad, double dt_s);

// The pendulum bench's voltage-controlled P servo (Dynamixel-style, BAM eq. 12–13):
//   duty = clip(error_gain·kp·(e + T_d·ė), −max_duty, +max_duty),  e = θ_d − θ,  U = supply_v·duty,
//   τ = K_t·U/R − K_t²·θ̇/R       (joint-side K_t and R; drive/brake H-bridge)
// With torque disabled the H-bridge is released and the torque is zero.
struct BenchServoParams {
  double kp = 32.0;                       // firmware P gain, vendor units
  double error_gain = 0.0028774;          // duty per (kp·rad)
  double max_duty = 1.0;                  // duty limit
  double supply_v = 7.4;                  // supply voltage
  double torque_constant_nm_per_a = 1.0;  // K_t, joint side
  double resistance_ohm = 2.6;            // R
  double torque_off_s = 1.0e9;            // log time from which the H-bridge is released
  // The driver's current limit I_max: the winding current (U − K_t·θ̇)/R is clamped to ±I_max
  // (motor.current_limit_a; the default 1e3 A never binds on a servo).
  double current_limit_a = 1.0e3;
  // The motor's torque saturation k = 1/I_s (motor.torque_saturation_per_a,
  // torque_saturation.hpp): τ = K_t·tanh(k·I)/k after the current limit; 0 = linear.
  double saturation_per_a = 0.0;
  // The firmware's derivative time T_d (s; bench.derivative_s, the effect servo_derivative): a
  // PD firmware's D on the error's rate ė = θ̇_d − θ̇, in the P gain's units. 0 = P only.
  double derivative_s = 0.0;
};
struct BenchServoOutput {
  double torque_nm = 0.0;  // on the joint
  double current_a = 0.0;  // through the winding (after the current limit, before saturation)
};
// `command_rate_rad_s` is θ̇_d, read only when params.derivative_s is not 0.
BenchServoOutput bench_servo_output(const BenchServoParams& params, double commanded_rad,
                                    double measured_rad, double velocity_rad_s, bool torque_enabled,
                                    double command_rate_rad_s = 0.0);
// The torque alone.
double bench_servo_torque_nm(const BenchServoParams& params, double commanded_rad,
                             double measured_rad, double velocity_rad_s, bool torque_enabled);

// motor.torque_saturation_per_a (the effect torque_saturation, read by the bench and firmware
// laws). Throws ModelError when negative.
double read_torque_saturation_per_a(const ParameterReader& get);

// "servo.<scope>." for a law's own per-joint or per-group parameters (ActuatorSpec::servo_scope;
// the joint's name when the scope is empty).
std::string servo_parameter_prefix(const ActuatorSpec& actuator);

// A torque servo's limits (pd_torque): ±τ_max, and with a no-load speed ω₀ > 0 the DC motor's
// linear torque–speed curve: the torque along the motion falls to 0 at θ̇ = ω₀ (upper limit
// τ_max·(1 − θ̇/ω₀) clipped to [0, τ_max], lower limit τ_max·(−1 − θ̇/ω₀) clipped to [−τ_max, 0]),
// while braking against the motion keeps τ_max. ω₀ = 0: no curve.
double clip_torque_speed_nm(double torque_nm, double velocity_rad_s, double torque_max_nm,
                            double no_load_speed_rad_s);

// The parameters of seed 001's PID → motor → gear pipeline for one actuator, shared by the
// `motoflex` and `motoflex_2011` laws: PID gains, motor, the actuator group's gear, and the
// joint's motor-load friction terms (friction_family.hpp, FrictionTerms::kMotorLoad).
std::vector<std::string> motoflex_pipeline_parameter_names(const ActuatorSpec& actuator);

// joint.<J>.armature_kg_m2 of a hinge (the reflected rotor inertia J_rotor·σ², kg·m²) or
// joint.<J>.armature_kg of a slider (the reflected mass J_rotor·σ², σ in rad/m: kg), which the
// rollout adds as joint-space inertia (ServoLaw::armature). Throws ModelError when negative.
std::string armature_parameter_name(const ActuatorSpec& actuator);
double read_armature(const ParameterReader& get, const ActuatorSpec& actuator);

// A firmware-style law's parameters for one actuator: servo.<scope>.<leaf> for each of its own
// leaves, then BAM's friction family (FrictionTerms::kFamily) and the armature (the dynamixel,
// feetech and pd_torque laws).
std::vector<std::string> scoped_law_parameter_names(const ActuatorSpec& actuator,
                                                    const std::vector<std::string>& leaves);

// Joint friction (a budget for a zero-velocity ODE motor, BAM's M1–M6) is in
// friction_family.hpp.

// Starting values of joint.<J>.friction and .viscous for a new robot folder: the URDF's
// <dynamics friction damping> or 0, searched in [0, max(1, effort/2, 5·start)] (N·m or N;
// N·m·s/rad or N·s/m) with effort the URDF's limit when it has one.
std::vector<ParameterDefault> joint_friction_defaults(const ActuatorSpec& joint,
                                                      const JointHints& hints);

}  // namespace motoflex
