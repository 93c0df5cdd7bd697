// `servo: dynamixel` — a Dynamixel in position-control mode (firmware_servo_law.hpp). Defaults:
// the XL330 of the BAM pendulum logs (bam.md §2c, XL330Actuator): 4096 ticks/rev, KP divisor
// 256 ("empirically observed"), PWM limit 885 = 100 % duty, 7.4 V, joint-side K_t and R (gear
// ratio 1, BAM's convention; K_t and R bounds of BAM's XL330). The I and D divisors (65536,
// 16) are the X-series control table's scaling (not in bam.md; both gains default to 0). An
// MX-64/106 (bam.md §2c: error_gain 0.158, max_pwm 0.9625, 15 V) is kp_divisor
// (4096/2π)/(0.158·pwm_full_scale), pwm_limit 0.9625·pwm_full_scale.

#include "firmware_servo_law.hpp"

namespace motoflex {
namespace {

std::vector<ParameterSpec> defaults(const RobotModel& model, std::size_t actuator) {
  static const std::vector<detail::FirmwareDefault> kXl330 = {
      {"kp", 400.0, 0.0, 16383.0},
      {"ki", 0.0, 0.0, 16383.0},
      {"kd", 0.0, 0.0, 16383.0},
      {"kp_divisor", 256.0, 1.0, 4096.0},
      {"ki_divisor", 65536.0, 1.0, 1.0e6},
      {"kd_divisor", 16.0, 1.0, 1024.0},
      {"ticks_per_rev", 4096.0, 256.0, 1.0e6},
      {"integer_ticks", 0.0, 0.0, 1.0},
      {"deadband_ticks", 0.0, 0.0, 50.0},
      {"pwm_limit", 885.0, 0.0, 885.0},
      {"pwm_full_scale", 885.0, 100.0, 10000.0},
      {"supply_v", 7.4, 5.0, 16.0},
      {"Kt_nm_per_a", 0.6, 0.1, 3.0},
      {"R_ohm", 2.6, 1.0, 6.0},
      {"gear_ratio", 1.0, 1.0, 1000.0},
      {"current_limit_a", 0.0, 0.0, 10.0},
      {"torque_off_s", 1.0e9, 0.0, 1.0e9}};
  return detail::firmware_law_defaults(model, actuator, kXl330);
}

}  // namespace

ServoLawInfo dynamixel_servo_law_info() {
  ServoLawInfo info{"dynamixel",
                    "Dynamixel position firmware: PID in ticks -> PWM duty -> DC motor -> joint, "
                    "BAM friction M1-M6",
                    detail::firmware_law_parameter_names, detail::create_firmware_law};
  info.default_parameters = defaults;
  return info;
}

}  // namespace motoflex
