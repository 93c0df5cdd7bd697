// The motor's torque saturation (torque_saturation.hpp), τ = K_t·tanh(k·I)/k, against its closed
// forms:
//  * k = 0 is the linear motor exactly; the small-current slope is K_t, the torque at I = I_s is
//    tanh(1)·K_t·I_s, and the winding current is recovered from the torque exactly;
//  * the bench law: an arm held at full duty against gravity settles where the saturated stall
//    torque K_t·tanh(k·U/R)/k meets m·g·l·sin θ, lower than the linear motor holds it;
//  * the firmware laws (h_bridge_motor): the stall torque N·K_t·tanh(k·I)/k, after the current
//    limit when both act.

#include "motoflex/sim/actuator/torque_saturation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "bench_stall_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/actuator/h_bridge_motor.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

TEST(TorqueSaturationTest, LinearAtZeroTanhShapedAboveAndBounded) {
  for (const double current_a : {-3.0, -0.2, 0.0, 1.0e-9, 0.7, 2.5}) {
    EXPECT_EQ(saturated_current_a(current_a, 0.0), current_a);
  }
  const double k_per_a = 0.8;  // I_s = 1.25 A
  const double is_a = 1.0 / k_per_a;
  EXPECT_NEAR(saturated_current_a(is_a, k_per_a), std::tanh(1.0) * is_a, 1e-15);
  EXPECT_NEAR(saturated_current_a(-is_a, k_per_a), -std::tanh(1.0) * is_a, 1e-15);
  // Small currents: I − k²·I³/3 + O(I⁵).
  const double small_a = 1.0e-3;
  EXPECT_NEAR(saturated_current_a(small_a, k_per_a),
              small_a - k_per_a * k_per_a * small_a * small_a * small_a / 3.0, 1e-16);
  // Bounded by I_s and monotone.
  double previous = -is_a;
  for (double current_a = -10.0; current_a <= 10.0; current_a += 0.25) {
    const double effective_a = saturated_current_a(current_a, k_per_a);
    EXPECT_LT(std::abs(effective_a), is_a);
    EXPECT_GT(effective_a, previous);
    previous = effective_a;
  }
}

// The bench stage reports the winding's current, which heats it, beside the saturated torque:
// the unsaturated (U − K_t·θ̇)/R, and I_max when the driver's limit binds.
TEST(TorqueSaturationTest, TheBenchStageReportsTheWindingCurrentBeforeTheSaturation) {
  BenchServoParams params;
  params.kp = 400.0;
  params.supply_v = 7.4;
  params.torque_constant_nm_per_a = 0.3;
  params.resistance_ohm = 2.6;
  params.saturation_per_a = 0.8;
  const double error_rad = 0.4;  // duty 0.46
  const double rate_rad_s = 1.5;
  const double duty = params.error_gain * params.kp * error_rad;
  const double current_a = (params.supply_v * duty - 0.3 * rate_rad_s) / 2.6;
  const BenchServoOutput out = bench_servo_output(params, error_rad, 0.0, rate_rad_s, true);
  EXPECT_NEAR(out.current_a, current_a, 1e-15);
  EXPECT_NEAR(out.torque_nm, 0.3 * std::tanh(0.8 * current_a) / 0.8, 1e-15);
  EXPECT_EQ(bench_servo_torque_nm(params, error_rad, 0.0, rate_rad_s, true), out.torque_nm);
  params.current_limit_a = 0.5;
  const BenchServoOutput limited = bench_servo_output(params, error_rad, 0.0, rate_rad_s, true);
  EXPECT_EQ(limited.current_a, 0.5);
  EXPECT_NEAR(limited.torque_nm, 0.3 * std::tanh(0.4) / 0.8, 1e-15);
  const BenchServoOutput released = bench_servo_output(params, error_rad, 0.0, rate_rad_s, false);
  EXPECT_EQ(released.current_a, 0.0);
  EXPECT_EQ(released.torque_nm, 0.0);
}

TEST(TorqueSaturationTest, ABenchArmAtFullDutyHoldsWhereTheSaturatedStallTorqueMeetsGravity) {
  const RobotModel bench = testing::load_servo_pendulum();
  ParameterSet v = testing::stall_bench_values(bench);
  EXPECT_EQ(v.get("motor.torque_saturation_per_a"), 0.0);  // linear by default
  const double goal_rad = testing::kBenchStallGoal_rad;
  const double mgl_nm = testing::bench_gravity_torque_nm(v);
  const double stall_a = v.get("bench.supply_v") / v.get("bench.R_ohm");  // 2.47 A at rest
  const double kt = v.get("bench.Kt_nm_per_a");

  const double linear_rad = testing::held_angle(bench, v, goal_rad, 60.0);
  const double k_per_a = 0.6;  // I_s = 1.67 A: the stall torque falls to 61 % of the linear one
  v.set("motor.torque_saturation_per_a", k_per_a);
  const double saturated_rad = testing::held_angle(bench, v, goal_rad, 60.0);
  const double linear_expected_rad = std::asin(kt * stall_a / mgl_nm);
  const double saturated_expected_rad =
      std::asin(kt * std::tanh(k_per_a * stall_a) / k_per_a / mgl_nm);
  std::printf("[ saturation ] held at %.6f rad (closed form %.6f), linear %.6f (%.6f)\n",
              saturated_rad, saturated_expected_rad, linear_rad, linear_expected_rad);
  EXPECT_GT(v.get("bench.error_gain") * v.get("bench.kp") * (goal_rad - linear_rad), 1.0);
  EXPECT_NEAR(linear_rad, linear_expected_rad, 1e-4);
  EXPECT_NEAR(saturated_rad, saturated_expected_rad, 1e-4);
  EXPECT_LT(saturated_rad, linear_rad - 0.2);

  v.set("motor.torque_saturation_per_a", -0.1);
  const RolloutResult rejected = testing::hold_bench(bench, v, goal_rad, 0.1);
  EXPECT_NE(rejected.end, RolloutEnd::kCompleted);
  EXPECT_NE(rejected.end_detail.find("motor.torque_saturation_per_a"), std::string::npos)
      << rejected.end_detail;
}

TEST(TorqueSaturationTest, TheHBridgeMotorSaturatesAfterItsCurrentLimit) {
  HBridgeMotorParams motor;
  motor.supply_v = 7.4;
  motor.torque_constant_nm_per_a = 0.003;
  motor.resistance_ohm = 2.6;
  motor.gear_ratio = 200.0;
  const double duty = 0.8;
  const double stall_a = motor.supply_v * duty / motor.resistance_ohm;  // 2.28 A
  const HBridgeMotorOutput linear = h_bridge_motor(motor, duty, 0.0);
  EXPECT_NEAR(linear.torque_nm, 0.6 * stall_a, 1e-12);
  motor.saturation_per_a = 0.5;
  const HBridgeMotorOutput saturated = h_bridge_motor(motor, duty, 0.0);
  EXPECT_NEAR(saturated.torque_nm, 0.6 * std::tanh(0.5 * stall_a) / 0.5, 1e-12);
  EXPECT_NEAR(saturated.current_a, stall_a, 1e-12);  // the winding's current, not saturated
  motor.current_limit_a = 1.0;
  const HBridgeMotorOutput both = h_bridge_motor(motor, duty, 0.0);
  EXPECT_NEAR(both.current_a, 1.0, 1e-12);
  EXPECT_NEAR(both.torque_nm, 0.6 * std::tanh(0.5) / 0.5, 1e-12);
  // No-load: the back-EMF cancels the drive, so no current and no torque, saturated or not.
  const double no_load_rad_s = motor.supply_v * duty / (0.003 * 200.0);
  EXPECT_NEAR(h_bridge_motor(motor, duty, no_load_rad_s).torque_nm, 0.0, 1e-12);
}

}  // namespace
}  // namespace motoflex
