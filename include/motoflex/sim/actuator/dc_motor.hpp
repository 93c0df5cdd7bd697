#pragma once

namespace motoflex {

// Electrical and mechanical constants of one DC motor, motor side (before the gear).
struct DcMotorParams {
  double supply_v = 21.6;         // battery voltage U_bat; the command is clamped to ±U_bat
  double resistance_ohm = 6.44;   // armature resistance R
  double inductance_h = 3.09e-4;  // armature inductance L
  double torque_constant_nm_per_a = 0.0195;  // K_t
  double stiffness = 1.0;             // S ∈ [0, 1], Aldebaran's stiffness factor (torque scale)
  double viscous_nm_s_per_rad = 0.0;  // B: back-EMF + viscous friction, per rad/s of motor speed
};

// Seed 001, Algorithm 1 (lines 2–6), with a symmetric clamp:
//   U   = clamp(U_cmd, −U_bat, +U_bat)
//   U_R ← U_R + (U − U_R)·(1 − exp(−dt·R/L))          (RL lag, exact for a constant U over dt)
//   T_M = U_R/R · S · K_t − B · ω_m                     (ω_m = motor speed, rad/s)
// One instance per joint, per rollout.
class DcMotor {
 public:
  // Throws std::invalid_argument if dt_s <= 0, R <= 0, L < 0 (L = 0 means no lag) or
  // U_bat < 0.
  DcMotor(const DcMotorParams& params, double dt_s);

  // Advances the RL circuit by one step and returns the motor-side torque in N·m.
  double update(double commanded_v, double motor_speed_rad_s);

  double resistor_voltage_v() const { return resistor_voltage_v_; }
  // Sets the circuit state (e.g. to start in steady state).
  void set_resistor_voltage_v(double volts) { resistor_voltage_v_ = volts; }
  // Changes the supply voltage and the armature resistance from now on (battery sag, a winding
  // heating up). Throws std::invalid_argument for R <= 0 or a negative supply.
  void set_operating_point(double supply_v, double resistance_ohm);
  // The armature current U_R/R in A.
  double current_a() const { return resistor_voltage_v_ / params_.resistance_ohm; }
  // The torque at zero speed with the full supply voltage: K_t·U_bat/R·S.
  double stall_torque_nm() const;
  const DcMotorParams& params() const { return params_; }

 private:
  void update_lag_fraction();

  DcMotorParams params_;
  double dt_s_;
  double lag_fraction_;  // 1 − exp(−dt·R/L), computed once
  double resistor_voltage_v_ = 0.0;
};

}  // namespace motoflex
