#pragma once

// The stages the servo laws are made of, as pure functions of their inputs (the laws in
// src/sim/actuator/*_servo_law.cpp hold the state and read the parameters).

#include <string>

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
//   duty = clip(error_gain·kp·(θ_d − θ), −max_duty, +max_duty),  U = supply_v·duty,
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
};
double bench_servo_torque_nm(const BenchServoParams& params, double commanded_rad,
                             double measured_rad, double velocity_rad_s, bool torque_enabled);

// Joint friction as a budget for a zero-velocity ODE motor (seed 001 §2; BAM's clipping
// friction models M1–M4): the motor row holds the joint still with up to
//   fmax = F_c + F_s·exp(−(θ̇/v_s)²) + K_v·|θ̇| + K_l·|τ_load|
// so the joint sticks while the other torques stay below fmax and slips above it. F_s is the
// Stribeck (stiction) excess at rest, v_s its velocity scale; K_l makes the friction grow with
// the torque the gear transmits (load-dependent friction, bam.md §2d). ODE applies the budget
// implicitly: it opposes the motion but can never reverse it.
struct JointFrictionParams {
  double coulomb_nm = 0.0;               // F_c
  double viscous_nm_s_per_rad = 0.0;     // K_v
  double stribeck_nm = 0.0;              // F_s
  double stribeck_velocity_rad_s = 0.1;  // v_s (> 0)
  double load_coefficient = 0.0;         // K_l, N·m of friction per N·m transmitted
};
MotorCommand joint_friction(const JointFrictionParams& params, double velocity_rad_s,
                            double load_torque_nm = 0.0);
// Reads joint.<joint>.{friction_nm, viscous_nm_s_per_rad, stribeck_nm, stribeck_velocity_rad_s,
// load_friction}. Throws ModelError for a negative value or a non-positive Stribeck velocity.
JointFrictionParams read_joint_friction(const ParameterReader& get, const std::string& joint);
// The names read_joint_friction reads, in its order.
std::vector<std::string> joint_friction_parameter_names(const std::string& joint);
// The same for any actuated joint: a prismatic joint's names are in N and m
// (joint.<J>.friction_n, viscous_n_s_per_m, stribeck_n, stribeck_velocity_m_s, load_friction).
JointFrictionParams read_joint_friction(const ParameterReader& get, const ActuatorSpec& joint);
std::vector<std::string> joint_friction_parameter_names(const ActuatorSpec& joint);
// Starting values of joint.<J>.friction and .viscous for a new robot folder: the URDF's
// <dynamics friction damping> or 0, searched in [0, max(1, effort/2, 5·start)] (N·m or N;
// N·m·s/rad or N·s/m) with effort the URDF's limit when it has one.
std::vector<ParameterDefault> joint_friction_defaults(const ActuatorSpec& joint,
                                                      const JointHints& hints);

}  // namespace motoflex
