#include "motoflex/sim/actuator/dc_motor.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace motoflex {
namespace {

// Nao-class values (the header defaults): L/R = 48 µs.
DcMotorParams nao_motor() {
  return DcMotorParams{};
}

TEST(DcMotorTest, RlLagIsExactExponentialAtEveryStep) {
  const DcMotorParams params = nao_motor();
  const double tau_s = params.inductance_h / params.resistance_ohm;
  const double command_v = 10.0;  // below U_bat: no clamp
  for (double dt_s : {1e-6, 1e-5, 1e-3}) {
    DcMotor motor(params, dt_s);
    for (int k = 1; k <= 300; ++k) {
      motor.update(command_v, 0.0);
      const double expected_v = command_v * (1.0 - std::exp(-k * dt_s / tau_s));
      ASSERT_NEAR(motor.resistor_voltage_v(), expected_v, 1e-12) << "dt " << dt_s << " step " << k;
    }
  }
}

TEST(DcMotorTest, ReachesOneMinusOneOverEAfterOneTimeConstant) {
  const DcMotorParams params = nao_motor();
  const double tau_s = params.inductance_h / params.resistance_ohm;
  DcMotor motor(params, tau_s / 100.0);
  for (int k = 0; k < 100; ++k) motor.update(10.0, 0.0);
  EXPECT_NEAR(motor.resistor_voltage_v(), 10.0 * (1.0 - std::exp(-1.0)), 1e-12);
}

TEST(DcMotorTest, ZeroInductanceHasNoLag) {
  DcMotorParams params = nao_motor();
  params.inductance_h = 0.0;
  DcMotor motor(params, 1e-3);
  motor.update(5.0, 0.0);
  EXPECT_EQ(motor.resistor_voltage_v(), 5.0);
}

TEST(DcMotorTest, StallTorqueIsClampedSupplyThroughResistance) {
  DcMotorParams params = nao_motor();
  params.stiffness = 0.8;
  const double expected_nm =
      params.torque_constant_nm_per_a * params.supply_v / params.resistance_ohm * params.stiffness;
  DcMotor motor(params, 1e-3);
  EXPECT_NEAR(motor.stall_torque_nm(), expected_nm, 1e-15);
  double torque_nm = 0.0;
  for (int k = 0; k < 50; ++k) torque_nm = motor.update(100.0, 0.0);  // far above U_bat
  EXPECT_EQ(motor.resistor_voltage_v(), params.supply_v);
  EXPECT_DOUBLE_EQ(torque_nm, motor.stall_torque_nm());
  // The clamp is symmetric: a large negative command stalls with the opposite torque.
  for (int k = 0; k < 50; ++k) torque_nm = motor.update(-100.0, 0.0);
  EXPECT_EQ(motor.resistor_voltage_v(), -params.supply_v);
  EXPECT_DOUBLE_EQ(torque_nm, -motor.stall_torque_nm());
}

TEST(DcMotorTest, BackEmfSubtractsViscousTimesSpeed) {
  DcMotorParams params = nao_motor();
  params.viscous_nm_s_per_rad = 2.5e-5;
  DcMotor motor(params, 1e-3);
  motor.set_resistor_voltage_v(6.0);
  const double drive_nm =
      6.0 / params.resistance_ohm * params.stiffness * params.torque_constant_nm_per_a;
  const double speed_rad_s = 300.0;
  // U_R is already at the command, so the lag leaves it there.
  EXPECT_NEAR(motor.update(6.0, speed_rad_s), drive_nm - 2.5e-5 * speed_rad_s, 1e-15);
  EXPECT_NEAR(motor.update(6.0, -speed_rad_s), drive_nm + 2.5e-5 * speed_rad_s, 1e-15);
}

TEST(DcMotorTest, RejectsInvalidParameters) {
  DcMotorParams params = nao_motor();
  EXPECT_THROW(DcMotor(params, 0.0), std::invalid_argument);
  params.resistance_ohm = 0.0;
  EXPECT_THROW(DcMotor(params, 1e-3), std::invalid_argument);
  params = nao_motor();
  params.inductance_h = -1e-4;
  EXPECT_THROW(DcMotor(params, 1e-3), std::invalid_argument);
  params = nao_motor();
  params.supply_v = -1.0;
  EXPECT_THROW(DcMotor(params, 1e-3), std::invalid_argument);
}

TEST(DcMotorTest, OperatingPointChangesStallTorqueAndTimeConstant) {
  DcMotorParams params;
  params.viscous_nm_s_per_rad = 0.0;
  const double dt = 1e-5;
  DcMotor motor(params, dt);
  // A heated winding (R × 1.2) and a sagging battery (21.6 → 20 V).
  const double hot_ohm = params.resistance_ohm * 1.2;
  motor.set_operating_point(20.0, hot_ohm);
  for (int k = 0; k < 20000; ++k) motor.update(100.0, 0.0);
  EXPECT_NEAR(motor.update(100.0, 0.0),
              20.0 / hot_ohm * params.stiffness * params.torque_constant_nm_per_a, 1e-12);
  EXPECT_NEAR(motor.current_a(), 20.0 / hot_ohm, 1e-12);
  // The RL time constant follows the new resistance: after L/R_hot the lag reached 1 − 1/e.
  motor.set_resistor_voltage_v(0.0);
  const int steps = static_cast<int>(std::lround(params.inductance_h / hot_ohm / dt));
  double u_r = 0.0;
  for (int k = 0; k < steps; ++k) {
    motor.update(10.0, 0.0);
    u_r = motor.resistor_voltage_v();
  }
  EXPECT_NEAR(u_r, 10.0 * (1.0 - std::exp(-steps * dt * hot_ohm / params.inductance_h)), 1e-9);
  EXPECT_THROW(motor.set_operating_point(20.0, 0.0), std::invalid_argument);
  EXPECT_THROW(motor.set_operating_point(-1.0, 6.0), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
