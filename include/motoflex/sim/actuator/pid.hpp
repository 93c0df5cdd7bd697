#pragma once

namespace motoflex {

// Gains of the servo's position controller; its output is a voltage (seed 001, Algorithm 1,
// line 1). The derivative acts on the error and is divided by dt (MoToFlex's code does not
// divide; its d gain equals kd_v_s_per_rad / dt_s).
struct PidGains {
  double kp_v_per_rad = 0.0;    // proportional gain, V per rad of error
  double ki_v_per_rad_s = 0.0;  // integral gain, V per (rad·s) of accumulated error
  double kd_v_s_per_rad = 0.0;  // derivative gain, V per (rad/s) of error rate
};

// Discrete PID at a fixed step dt_s: u = kp·e + ki·Σe·dt + kd·(e − e_prev)/dt.
// The first update after reset() uses a zero derivative. One instance per joint, per rollout.
class Pid {
 public:
  // Throws std::invalid_argument if dt_s <= 0.
  Pid(const PidGains& gains, double dt_s);

  // error_rad = commanded − measured angle. Returns the voltage command in V (unclamped).
  double update(double error_rad);

  // Clears the integral; the next update has no derivative term.
  void reset();
  // Preloads the integral so that a constant error of zero produces `output_v` (used to start
  // a rollout in a settled state). Throws ModelError if ki is 0 and output_v is not.
  void preload_integral(double output_v);

  double integral_rad_s() const { return integral_rad_s_; }

 private:
  PidGains gains_;
  double dt_s_;
  double integral_rad_s_ = 0.0;
  double previous_error_rad_ = 0.0;
  bool has_previous_ = false;
};

}  // namespace motoflex
