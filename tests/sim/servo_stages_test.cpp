#include "motoflex/sim/actuator/servo_stages.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include <stdexcept>

#include "motoflex/sim/actuator/friction_family.hpp"

namespace motoflex {
namespace {

TEST(ServoStagesTest, VelocityServoFollowsEq3WithTorqueLimit) {
  const VelocityServoParams params{.gain_per_s = 4.0, .torque_max_nm = 10.0};
  // θ̇_d = −k_d(θ − θ_d): 0.5 rad short of the target → +2 rad/s.
  MotorCommand command = velocity_servo(params, 0.5, 0.0);
  EXPECT_DOUBLE_EQ(command.velocity_rad_s, 2.0);
  EXPECT_EQ(command.fmax_nm, 10.0);  // ODE's motor row clips the torque at τ_max
  command = velocity_servo(params, -0.25, 0.5);
  EXPECT_DOUBLE_EQ(command.velocity_rad_s, -3.0);
  EXPECT_EQ(command.fmax_nm, 10.0);
  EXPECT_EQ(velocity_servo(params, 1.2, 1.2).velocity_rad_s, 0.0);
}

TEST(ServoStagesTest, IdealServoReachesNextTargetInOneStep) {
  const MotorCommand command = ideal_servo({.torque_max_nm = 100.0}, 0.31, 0.3, 1e-3);
  EXPECT_NEAR(command.velocity_rad_s, 10.0, 1e-9);
  EXPECT_EQ(command.fmax_nm, 100.0);
  EXPECT_THROW(ideal_servo({}, 0.0, 0.0, 0.0), std::invalid_argument);
}

TEST(ServoStagesTest, BenchServoStallsAtClippedDuty) {
  BenchServoParams params;
  params.max_duty = 0.9;
  // A large error saturates the duty (0.0028774·32·20 = 1.84 > 0.9): τ = K_t·V·max_duty/R at
  // zero speed.
  const double stall_nm =
      params.torque_constant_nm_per_a * params.supply_v * params.max_duty / params.resistance_ohm;
  EXPECT_DOUBLE_EQ(bench_servo_torque_nm(params, 20.0, 0.0, 0.0, true), stall_nm);
  EXPECT_DOUBLE_EQ(bench_servo_torque_nm(params, -20.0, 0.0, 0.0, true), -stall_nm);
}

TEST(ServoStagesTest, BenchServoLinearRegionAndBackEmf) {
  BenchServoParams params;
  params.torque_constant_nm_per_a = 0.8;
  const double error_rad = 0.1;  // duty = 0.0028774·32·0.1 = 0.0092, unclipped
  const double duty = params.error_gain * params.kp * error_rad;
  ASSERT_LT(duty, params.max_duty);
  const double kt = params.torque_constant_nm_per_a;
  const double r = params.resistance_ohm;
  EXPECT_NEAR(bench_servo_torque_nm(params, error_rad, 0.0, 0.0, true),
              kt * params.supply_v * duty / r, 1e-15);
  // The back-EMF brakes the motion in either direction, even with zero error.
  EXPECT_NEAR(bench_servo_torque_nm(params, 0.0, 0.0, 2.0, true), -kt * kt * 2.0 / r, 1e-15);
  EXPECT_NEAR(bench_servo_torque_nm(params, 0.0, 0.0, -2.0, true), kt * kt * 2.0 / r, 1e-15);
  EXPECT_NEAR(bench_servo_torque_nm(params, error_rad, 0.0, 2.0, true),
              kt * params.supply_v * duty / r - kt * kt * 2.0 / r, 1e-15);
}

TEST(ServoStagesTest, BenchServoCurrentLimitCapsTheTorqueWhateverTheDuty) {
  BenchServoParams params;
  params.torque_constant_nm_per_a = 0.39;
  params.resistance_ohm = 3.6;
  params.kp = 800.0;
  const double kt = params.torque_constant_nm_per_a;
  // Saturated duty at stall: I = 7.4 V / 3.6 Ω = 2.06 A, above a 1.4 A limit: τ = K_t·1.4 A.
  const double unlimited_nm = bench_servo_torque_nm(params, 1.0, 0.0, 0.0, true);
  EXPECT_NEAR(unlimited_nm, kt * params.supply_v / params.resistance_ohm, 1e-15);
  params.current_limit_a = 1.4;
  EXPECT_DOUBLE_EQ(bench_servo_torque_nm(params, 1.0, 0.0, 0.0, true), kt * 1.4);
  EXPECT_DOUBLE_EQ(bench_servo_torque_nm(params, -1.0, 0.0, 0.0, true), -kt * 1.4);
  // Below the limit (a small error, or the back-EMF of a fast motion cutting the current) the
  // torque is the unlimited law's, bit for bit: 0.05 rad → I = 0.24 A; 1 rad at 20 rad/s →
  // (7.4 − 7.8) V / 3.6 Ω = −0.11 A.
  BenchServoParams unlimited = params;
  unlimited.current_limit_a = 1.0e3;
  EXPECT_EQ(bench_servo_torque_nm(params, 0.05, 0.0, 0.0, true),
            bench_servo_torque_nm(unlimited, 0.05, 0.0, 0.0, true));
  EXPECT_EQ(bench_servo_torque_nm(params, 1.0, 0.0, 20.0, true),
            bench_servo_torque_nm(unlimited, 1.0, 0.0, 20.0, true));
  // Braking current is limited too: driven backwards hard at full reverse duty.
  EXPECT_DOUBLE_EQ(bench_servo_torque_nm(params, -1.0, 0.0, 10.0, true), -kt * 1.4);
}

TEST(ServoStagesTest, BenchServoWithTorqueDisabledIsFree) {
  const BenchServoParams params;
  EXPECT_EQ(bench_servo_torque_nm(params, 3.0, 0.0, 5.0, false), 0.0);
}

TEST(ServoStagesTest, JointFrictionBudgetIsCoulombPlusViscous) {
  const FrictionParams params{.coulomb_nm = 0.05, .viscous_nm_s_per_rad = 0.2};
  MotorCommand command = joint_friction(params, 0.0);
  EXPECT_EQ(command.velocity_rad_s, 0.0);
  EXPECT_EQ(command.fmax_nm, 0.05);
  command = joint_friction(params, -1.5);
  EXPECT_EQ(command.velocity_rad_s, 0.0);
  EXPECT_DOUBLE_EQ(command.fmax_nm, 0.05 + 0.2 * 1.5);  // symmetric in the direction of motion
  EXPECT_DOUBLE_EQ(joint_friction(params, 1.5).fmax_nm, command.fmax_nm);
}

TEST(ServoStagesTest, StribeckAndLoadDependentFrictionBudget) {
  const FrictionParams params{.coulomb_nm = 0.1,
                              .viscous_nm_s_per_rad = 0.2,
                              .stribeck_nm = 0.3,
                              .stribeck_velocity_rad_s = 0.05,
                              .load_motor = 0.1};
  // At rest the full breakaway torque F_c + F_s holds the joint (plus K_l·|τ|).
  EXPECT_DOUBLE_EQ(joint_friction(params, 0.0).fmax_nm, 0.4);
  EXPECT_DOUBLE_EQ(joint_friction(params, 0.0, -2.0).fmax_nm, 0.4 + 0.2);
  // At v = v_s the Stribeck excess has fallen to F_s/e.
  EXPECT_DOUBLE_EQ(joint_friction(params, 0.05).fmax_nm, 0.1 + 0.2 * 0.05 + 0.3 / std::exp(1.0));
  // Far above v_s only Coulomb + viscous remain.
  EXPECT_NEAR(joint_friction(params, -2.0).fmax_nm, 0.1 + 0.4, 1e-12);
}

}  // namespace
}  // namespace motoflex
