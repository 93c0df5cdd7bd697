// `servo: bench` scales its winding resistance to the log's housing temperature:
// R = R_25·(1 + α·(T − 25 °C)), α = motor.R_temperature_per_k, T = motor.housing_temperature_c
// (each BAM log's sidecar). Held against gravity at full duty with no dry friction, the arm
// settles where the stall torque K_t·U/R(T) equals m·g·l·sin q, so a warmer log holds lower,
// exactly as the resistance says; α = 0 ignores the temperature.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;  // the rollout's world gravity

const RobotModel& pendulum() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum", StructureOptions{});
  return model;
}

ParameterSet stall_bench(double r_per_k, double housing_c) {
  ParameterSet p(pendulum().parameters);
  p.set("joint.pendulum.friction_nm", 0.0);
  p.set("joint.pendulum.viscous_nm_s_per_rad", 0.05);  // settles the arm, not the hold angle
  p.set("bench.Kt_nm_per_a", 0.1);
  p.set("bench.R_ohm", 2.6);
  p.set("bench.supply_v", 6.0);
  p.set("motor.R_temperature_per_k", r_per_k);
  p.set("motor.housing_temperature_c", housing_c);
  return p;
}

// The goal straight up, far beyond what the motor lifts: the duty saturates at 1.
CommandTrajectory goal_up(double seconds) {
  std::vector<double> t, q;
  for (int k = 0; k * 0.005 <= seconds + 1e-9; ++k) {
    t.push_back(0.005 * k);
    q.push_back(std::numbers::pi);
  }
  return CommandTrajectory(t, q, 1);
}

RolloutResult hold(const ParameterSet& p, double seconds) {
  RolloutOptions options;
  options.servo = "bench";
  return run_rollout(pendulum(), p, goal_up(seconds), options);
}

TEST(BenchHousingTemperature, HoldAngleFollowsTheResistanceAtTheLoggedTemperature) {
  const double r_per_k = 0.02;
  for (const double housing_c : {25.0, 45.0, 65.0}) {
    const ParameterSet p = stall_bench(r_per_k, housing_c);
    const RolloutResult result = hold(p, 10.0);
    ASSERT_EQ(result.frames_completed, result.frames_requested);
    const double r_ohm = 2.6 * (1.0 + r_per_k * (housing_c - 25.0));  // 2.6, 3.64, 4.68 Ω
    const double expected = std::asin(
        0.1 * 6.0 / r_ohm / (p.get("bench.mass_kg") * kGravity_m_s2 * p.get("bench.length_m")));
    EXPECT_NEAR(std::abs(result.measured_rad.back()), expected, 2e-3) << housing_c << " C";
  }
  // α = 0 (the default): the temperature is ignored, bit for bit.
  const RolloutResult cold = hold(stall_bench(0.0, 25.0), 1.0);
  const RolloutResult hot = hold(stall_bench(0.0, 80.0), 1.0);
  EXPECT_EQ(cold.measured_rad, hot.measured_rad);
}

TEST(BenchHousingTemperature, ANonPositiveResistanceIsAModelError) {
  // 1 + 0.05·(−40 − 25) < 0.
  const RolloutResult result = hold(stall_bench(0.05, -40.0), 0.1);
  EXPECT_EQ(result.end, RolloutEnd::kModelError);
  EXPECT_NE(result.end_detail.find("motor.R_temperature_per_k"), std::string::npos)
      << result.end_detail;
}

}  // namespace
}  // namespace motoflex
