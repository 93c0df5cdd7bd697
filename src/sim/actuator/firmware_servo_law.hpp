#pragma once

// Internal to the servo laws: a position-control smart servo (dynamixel, feetech) — the
// firmware's P(I)D in register units → PWM duty (position_firmware.hpp) → H-bridge DC motor with
// back-EMF, optional gear and current limit (h_bridge_motor.hpp) → joint, with joint friction
// from BAM's family M1–M6 (friction_family.hpp) on the motor torque and the external (gravity)
// torque, and the armature as joint inertia. The vendors differ in their register defaults.
//
// Parameters, `servo.<scope>.` + kp, ki, kd, kp_divisor, ki_divisor, kd_divisor, ticks_per_rev,
// integer_ticks (0/1), deadband_ticks, pwm_limit, pwm_full_scale, supply_v, Kt_nm_per_a, R_ohm,
// gear_ratio, current_limit_a (0 = none), torque_off_s; joint.<J>.* friction and armature.

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex::detail {

// A vendor's defaults and search bounds, one triple per parameter.
struct FirmwareDefault {
  const char* leaf;  // e.g. "kp_divisor"
  double value, lower, upper;
};

std::vector<std::string> firmware_law_parameter_names(const RobotModel& model,
                                                      std::size_t actuator);
std::unique_ptr<ServoLaw> create_firmware_law(const ServoLawSetup& setup);
std::vector<ParameterSpec> firmware_law_defaults(const RobotModel& model, std::size_t actuator,
                                                 const std::vector<FirmwareDefault>& vendor);

}  // namespace motoflex::detail
