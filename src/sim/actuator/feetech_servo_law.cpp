// `servo: feetech` — a Feetech STS/SCS servo in position mode (firmware_servo_law.hpp). bam.md
// documents no Feetech firmware (the STS3250 logs' kp 32 is nominal: the recorder could not set
// it, §1b), so only what the logs state is a default with a source: 12 V supply and kp 32. The
// 4096-tick encoder, PWM full scale 1000 (the torque-limit register's 100 %), the KP divisor 32
// (1 PWM count per tick at kp 32), K_t 1.0 N·m/A and R 2.5 Ω (stall K_t·U/R ≈ 4.8 N·m, the
// STS3250's class) are starting values with wide bounds, to be identified.

#include "firmware_servo_law.hpp"

namespace motoflex {
namespace {

std::vector<ParameterSpec> defaults(const RobotModel& model, std::size_t actuator) {
  static const std::vector<detail::FirmwareDefault> kSts = {
      {"kp", 32.0, 0.0, 255.0},
      {"ki", 0.0, 0.0, 255.0},
      {"kd", 0.0, 0.0, 255.0},
      {"kp_divisor", 32.0, 1.0, 4096.0},
      {"ki_divisor", 65536.0, 1.0, 1.0e6},
      {"kd_divisor", 16.0, 1.0, 1024.0},
      {"ticks_per_rev", 4096.0, 256.0, 1.0e6},
      {"integer_ticks", 0.0, 0.0, 1.0},
      {"deadband_ticks", 0.0, 0.0, 50.0},
      {"pwm_limit", 1000.0, 0.0, 1000.0},
      {"pwm_full_scale", 1000.0, 100.0, 10000.0},
      {"supply_v", 12.0, 5.0, 16.0},
      {"Kt_nm_per_a", 1.0, 0.1, 5.0},
      {"R_ohm", 2.5, 0.5, 10.0},
      {"gear_ratio", 1.0, 1.0, 1000.0},
      {"current_limit_a", 0.0, 0.0, 10.0},
      {"torque_off_s", 1.0e9, 0.0, 1.0e9}};
  return detail::firmware_law_defaults(model, actuator, kSts);
}

}  // namespace

ServoLawInfo feetech_servo_law_info() {
  ServoLawInfo info{"feetech",
                    "Feetech position firmware: PID in ticks -> PWM duty -> DC motor -> joint, "
                    "BAM friction M1-M6",
                    detail::firmware_law_parameter_names, detail::create_firmware_law};
  info.default_parameters = defaults;
  return info;
}

}  // namespace motoflex
