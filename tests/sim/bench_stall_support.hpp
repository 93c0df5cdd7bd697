#pragma once

// The pendulum bench's arm driven at full duty against gravity (a goal it cannot reach), for the
// tests of what weakens a stalled motor (winding_heating_test.cpp, torque_saturation_test.cpp):
// the closed forms hold because the duty stays saturated and the arm comes to rest.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex::testing {

constexpr double kBenchGravity_m_s2 = 9.81;  // the rollout's world gravity
constexpr double kBenchStallGoal_rad = 1.5;

inline RobotModel load_servo_pendulum() {
  return load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum",
                          StructureOptions{});
}

// Nominal supply 7.4 V, kp 2000 (duty 5.75 per rad of error: saturated well short of the goal),
// K_t 0.15 N·m/A, R 3 Ω, no Coulomb friction, viscous 0.05 N·m·s/rad.
inline ParameterSet stall_bench_values(const RobotModel& bench) {
  ParameterSet v(bench.parameters);
  v.set("bench.logged_supply", 0.0);
  v.set("bench.supply_v", 7.4);
  v.set("bench.kp", 2000.0);
  v.set("bench.Kt_nm_per_a", 0.15);
  v.set("bench.R_ohm", 3.0);
  v.set("joint.pendulum.friction_nm", 0.0);
  v.set("joint.pendulum.viscous_nm_s_per_rad", 0.05);
  return v;
}

// m·g·l of the arm (N·m): the gravity torque at 90°.
inline double bench_gravity_torque_nm(const ParameterSet& v) {
  return v.get("bench.mass_kg") * kBenchGravity_m_s2 * v.get("bench.length_m");
}

// The bench arm held at `goal_rad` for `hold_s`.
inline RolloutResult hold_bench(const RobotModel& bench, const ParameterSet& v, double goal_rad,
                                double hold_s) {
  const CommandTrajectory command =
      keyframe_trajectory({{0.0, {goal_rad}}, {hold_s, {goal_rad}}}, 100.0);
  RolloutOptions options;
  options.servo = "bench";
  return run_rollout(bench, v, command, options);
}

// The arm's angle at the end of that hold (NaN, and a failure, when the rollout did not end).
inline double held_angle(const RobotModel& bench, const ParameterSet& v, double goal_rad,
                         double hold_s) {
  const RolloutResult r = hold_bench(bench, v, goal_rad, hold_s);
  EXPECT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
  return r.measured_rad.empty() ? std::nan("") : r.measured_rad.back();
}

}  // namespace motoflex::testing
