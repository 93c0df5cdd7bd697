#pragma once

// BAM's servo calibration tables (shared/data/bam/mx64, mx106: Rhoban/bam commit c50ae40),
// the two bench measurements that come before any trajectory log:
//  * no-load speed vs voltage, `{ "<volts>": <speed rad/s>, ... }`: at no load the supply is
//    back-EMF plus what the friction current drops on the winding, V = k_e·ω + R·I₀, so the
//    slope is the back-EMF constant k_e [V·s/rad], numerically the joint-side torque constant
//    K_t [N·m/A]; BAM fits V = k·ω through the origin;
//  * PWM on-time vs position error, `{ "pwm_period": P, "samples": [{target, position [deg],
//    voltage [V], kp, period}] }`: the mean winding voltage U = voltage·period/P against
//    kp·|target − position| [kp·rad] gives the firmware gain H [V per kp·rad] (BAM: through
//    the origin), so the duty per kp·rad (BAM's error_gain) is H/voltage.
// Each is fitted both ways with 95 % intervals (core/line_fit.hpp).

#include <string>
#include <vector>

#include "motoflex/core/line_fit.hpp"

namespace motoflex {

struct SpeedVoltageCalibration {
  std::vector<double> volts;        // supply, V
  std::vector<double> speed_rad_s;  // no-load speed
  LineFit through_origin;           // V = k·ω (BAM's fit)
  LineFit affine;                   // V = k_e·ω + V₀, V₀ = R·I₀
};

struct PwmGainCalibration {
  double pwm_period = 0.0;            // the oscilloscope's PWM period (unit of `period`)
  std::vector<double> kp_error_rad;   // kp·|target − position|
  std::vector<double> winding_volts;  // voltage·period/pwm_period
  double supply_v = 0.0;              // the samples' voltage (all equal)
  LineFit through_origin;             // U = H·kp·e (BAM's fit)
  LineFit affine;                     // U = H·kp·e + U₀
  double error_gain = 0.0;            // H/supply: duty per kp·rad
  double error_gain_ci95 = 0.0;       // half-width
  // The `dynamixel` law's KP divisor for this gain with 4096 ticks per turn and PWM full scale
  // 885 (error_gain = (4096/2π)/(kp_divisor·885)).
  double dynamixel_kp_divisor = 0.0;
};

struct ServoCalibrationTable {
  enum class Kind { kSpeedVoltage, kPwmGain };
  Kind kind = Kind::kSpeedVoltage;
  SpeedVoltageCalibration speed;  // when kind == kSpeedVoltage
  PwmGainCalibration pwm;         // when kind == kPwmGain
};

// Reads and fits one table. Throws InputError(shown, 0, field, ...) naming the field for a file
// that is neither kind, a value that is missing or not a finite number, samples at different
// voltages, or too few points to fit.
ServoCalibrationTable read_servo_calibration_table(const std::string& path,
                                                   const std::string& shown);

}  // namespace motoflex
