#pragma once

// The position loop of a smart servo's firmware (Dynamixel, Feetech) in its own register units:
// the error in encoder ticks, the P, I and D registers with the vendor's divisors, a PWM output
// in counts clipped at the PWM limit, and the duty cycle = PWM / full scale (bam.md §2c: the
// XL330's duty = clip(kp·e_ticks/256, ±885)/885 with e_ticks = (θ_d − θ)·4096/2π, i.e. BAM's
// error_gain (4096/2π)/(256·885) per kp·rad).
//
// Firmware details that make a real servo stall short of its goal are switches with neutral
// defaults: integer position resolution (the error is a whole number of ticks), a dead band
// (the error counts as 0 within ±deadband_ticks).

namespace motoflex {

struct PositionFirmwareParams {
  double ticks_per_rev = 4096.0;  // encoder resolution (12 bits on XL330 and STS servos)
  double kp = 400.0;              // P gain register
  double ki = 0.0;                // I gain register
  double kd = 0.0;                // D gain register
  double kp_divisor = 256.0;      // PWM counts = kp·e/kp_divisor (XL330: 256, bam.md §2c)
  double ki_divisor = 65536.0;    // + ki·Σe/ki_divisor, Σ over firmware cycles of 1 ms
  double kd_divisor = 16.0;       // + kd·Δe/kd_divisor, Δ per firmware cycle of 1 ms
  double pwm_limit = 885.0;       // |PWM| limit register, counts
  double pwm_full_scale = 885.0;  // PWM counts of 100 % duty
  double deadband_ticks = 0.0;    // |e| ≤ this counts as 0 (0 = none)
  bool integer_ticks = false;     // goal and position rounded to whole ticks
};

// One servo's firmware state (the I sum and the previous error). The firmware runs once per
// physics step; its I and D registers are scaled to a 1 ms firmware cycle.
class PositionFirmware {
 public:
  // Throws std::invalid_argument for ticks_per_rev, divisors or pwm_full_scale not > 0, or a
  // negative gain, PWM limit or dead band.
  PositionFirmware(const PositionFirmwareParams& params, double dt_s);

  // The position error in ticks the firmware acts on (rounding and dead band applied).
  double error_ticks(double goal_rad, double position_rad) const;
  // Advances one step and returns the duty cycle in [−pwm_limit, +pwm_limit]/pwm_full_scale.
  double update(double goal_rad, double position_rad);

  const PositionFirmwareParams& params() const { return params_; }

 private:
  PositionFirmwareParams params_;
  double cycles_per_step_;  // physics step / 1 ms firmware cycle
  double sum_ticks_ = 0.0;  // Σe over firmware cycles (I register's input)
  double previous_ticks_ = 0.0;
  bool first_ = true;
};

}  // namespace motoflex
