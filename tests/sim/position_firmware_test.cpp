// The smart-servo stages on their own: the firmware's position loop in register units
// (bam.md §2c) and the H-bridge DC motor (BAM eq. 12–13, current limit), against the formulas.

#include "motoflex/sim/actuator/position_firmware.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "motoflex/sim/actuator/h_bridge_motor.hpp"

namespace motoflex {
namespace {

constexpr double kTicksPerRad = 4096.0 / (2.0 * std::numbers::pi);

TEST(PositionFirmwareTest, XL330DutyIsBamsErrorGainLaw) {
  // BAM's XL330: duty = clip(error_gain·kp·e, ±1), error_gain = (4096/2π)/(256·885).
  const double error_gain = kTicksPerRad / (256.0 * 885.0);
  EXPECT_NEAR(error_gain, 0.0028774, 1e-7);  // the value bam.md §2c quotes
  for (const double kp : {100.0, 400.0, 800.0}) {
    PositionFirmwareParams p;
    p.kp = kp;
    PositionFirmware firmware(p, 1e-3);
    for (const double error : {0.0, 0.01, -0.2, 0.5, -3.0}) {
      const double expected = std::min(std::max(error_gain * kp * error, -1.0), 1.0);
      EXPECT_NEAR(firmware.update(0.3 + error, 0.3), expected, 1e-14) << kp << " " << error;
    }
  }
}

TEST(PositionFirmwareTest, PwmLimitBelowFullScaleCapsTheDuty) {
  PositionFirmwareParams p;
  p.pwm_limit = 600.0;
  PositionFirmware firmware(p, 1e-3);
  EXPECT_DOUBLE_EQ(firmware.update(2.0, 0.0), 600.0 / 885.0);
  EXPECT_DOUBLE_EQ(firmware.update(-2.0, 0.0), -600.0 / 885.0);
}

TEST(PositionFirmwareTest, IntegerTicksAndDeadBand) {
  PositionFirmwareParams p;
  p.integer_ticks = true;
  const PositionFirmware whole(p, 1e-3);
  // 0.4 tick short: both registers round to the same count, no error at all.
  EXPECT_EQ(whole.error_ticks(0.4 / kTicksPerRad, 0.0), 0.0);
  EXPECT_EQ(whole.error_ticks(0.6 / kTicksPerRad, 0.0), 1.0);
  EXPECT_EQ(whole.error_ticks(3.7 / kTicksPerRad, 0.2 / kTicksPerRad), 4.0);
  p.integer_ticks = false;
  p.deadband_ticks = 5.0;
  const PositionFirmware band(p, 1e-3);
  EXPECT_EQ(band.error_ticks(4.9 / kTicksPerRad, 0.0), 0.0);
  EXPECT_EQ(band.error_ticks(-5.0 / kTicksPerRad, 0.0), 0.0);
  EXPECT_NEAR(band.error_ticks(5.5 / kTicksPerRad, 0.0), 5.5, 1e-12);  // outside: the full error
}

TEST(PositionFirmwareTest, IntegralAndDerivativeRegisters) {
  PositionFirmwareParams p;
  p.kp = 0.0;
  p.ki = 1000.0;
  PositionFirmware integral(p, 2e-3);    // 2 firmware cycles per physics step
  const double e = 10.0 / kTicksPerRad;  // 10 ticks
  for (int k = 1; k <= 5; ++k) {
    // Σe = 10 ticks · 2 cycles · k; PWM = ki·Σe/65536.
    EXPECT_NEAR(integral.update(e, 0.0), 1000.0 * 20.0 * k / 65536.0 / 885.0, 1e-12) << k;
  }
  p.ki = 0.0;
  p.kd = 160.0;
  PositionFirmware derivative(p, 1e-3);
  EXPECT_EQ(derivative.update(e, 0.0), 0.0);  // no kick on the first cycle
  // The error grows by 10 ticks per 1 ms cycle: PWM = kd·10/16.
  EXPECT_NEAR(derivative.update(2.0 * e, 0.0), 160.0 * 10.0 / 16.0 / 885.0, 1e-12);
  p.kp = -1.0;
  EXPECT_THROW(PositionFirmware(p, 1e-3), std::invalid_argument);
}

TEST(HBridgeMotorTest, BamEquationsWithGearAndCurrentLimit) {
  HBridgeMotorParams motor{.supply_v = 7.4,
                           .torque_constant_nm_per_a = 0.4,
                           .resistance_ohm = 2.6,
                           .gear_ratio = 1.0,
                           .current_limit_a = 0.0};
  // BAM eq. 13: τ = K_t·U/R − K_t²·θ̇/R.
  HBridgeMotorOutput out = h_bridge_motor(motor, 0.5, 3.0);
  EXPECT_NEAR(out.torque_nm, 0.4 * 7.4 * 0.5 / 2.6 - 0.4 * 0.4 * 3.0 / 2.6, 1e-15);
  // A gear: K_t on the motor, N = 200: stall N·K_t·U/R, back-EMF N²·K_t²/R on the joint.
  motor.torque_constant_nm_per_a = 0.002;
  motor.gear_ratio = 200.0;
  out = h_bridge_motor(motor, 1.0, 2.0);
  EXPECT_NEAR(out.torque_nm, 200.0 * 0.002 * 7.4 / 2.6 - 200.0 * 200.0 * 0.002 * 0.002 * 2.0 / 2.6,
              1e-14);
  // The current limit caps |I| at I_max: at stall the torque is N·K_t·I_max.
  motor.current_limit_a = 1.5;
  out = h_bridge_motor(motor, 1.0, 0.0);
  EXPECT_NEAR(out.current_a, 1.5, 1e-12);
  EXPECT_NEAR(out.torque_nm, 200.0 * 0.002 * 1.5, 1e-12);
  // Below the limit it does nothing.
  out = h_bridge_motor(motor, 0.1, 0.0);
  EXPECT_NEAR(out.current_a, 7.4 * 0.1 / 2.6, 1e-15);
}

}  // namespace
}  // namespace motoflex
