// The joint's mounting offset (the effect mounting_offset, BAM's q_offset): the servo and the
// log read θ + m while gravity acts on θ. On the pendulum bench, frictionless but damped:
//  * a released arm comes to rest where gravity puts it, θ = 0, and the log reads m;
//  * a P servo holding a goal g settles where K·(g − r) = M·g·l·sin(r − m), r the reading,
//    K the servo's stiffness at standstill; a log-only encoder offset of the same size shifts
//    the reading by m instead, which this equation does not give.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/keyframe_motion.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;  // the rollout's world gravity
constexpr double kMount_rad = 0.05;
constexpr double kGoal_rad = 0.5;

RobotModel bench_model() {
  return load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum",
                          StructureOptions{});
}

// Frictionless, damped by a viscous term and the back-EMF, driven at the nominal supply.
ParameterSet damped(const RobotModel& bench) {
  ParameterSet v(bench.parameters);
  v.set("joint.pendulum.friction_nm", 0.0);
  v.set("joint.pendulum.viscous_nm_s_per_rad", 0.05);
  v.set("bench.logged_supply", 0.0);
  return v;
}

// The last logged reading of a 4 s hold of `goal_rad`.
double final_reading(const RobotModel& bench, const ParameterSet& v, double goal_rad) {
  const CommandTrajectory hold = keyframe_trajectory({{0.0, {goal_rad}}, {4.0, {goal_rad}}}, 100.0);
  RolloutOptions options;
  options.servo = "bench";
  const RolloutResult r = run_rollout(bench, v, hold, options);
  EXPECT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
  return r.measured_rad.back();
}

// Newton on K·(g − r) − M·g·l·sin(r − m) = 0 (the servo unsaturated at the root).
double servo_rest_reading(const ParameterSet& v, double goal_rad, double mount_rad) {
  const double stiffness_nm_per_rad = v.get("bench.Kt_nm_per_a") * v.get("bench.supply_v") *
                                      v.get("bench.error_gain") * v.get("bench.kp") /
                                      v.get("bench.R_ohm");
  const double mgl_nm = v.get("bench.mass_kg") * kGravity_m_s2 * v.get("bench.length_m");
  double r = goal_rad;
  for (int k = 0; k < 50; ++k) {
    const double f = stiffness_nm_per_rad * (goal_rad - r) - mgl_nm * std::sin(r - mount_rad);
    const double df = -stiffness_nm_per_rad - mgl_nm * std::cos(r - mount_rad);
    r -= f / df;
  }
  EXPECT_LT(v.get("bench.error_gain") * v.get("bench.kp") * (goal_rad - r), 1.0);
  return r;
}

TEST(MountingOffsetTest, AReleasedArmRestsWhereGravityPutsItAndTheLogReadsTheOffset) {
  const RobotModel bench = bench_model();
  ParameterSet v = damped(bench);
  v.set("bench.torque_off_s", 0.0);  // released from the start
  // No back-EMF braking once released: 0.1 N·m·s/rad decays the swing as e^(−t/0.2 s).
  v.set("joint.pendulum.viscous_nm_s_per_rad", 0.1);
  const double plain = final_reading(bench, v, kGoal_rad);
  v.set("joint.pendulum.mounting_offset_rad", kMount_rad);
  const double mounted = final_reading(bench, v, kGoal_rad);
  std::printf("[ released ] rest reading: %.3e rad without, %.6f rad with m = %.2f\n", plain,
              mounted, kMount_rad);
  EXPECT_NEAR(plain, 0.0, 1e-5);
  EXPECT_NEAR(mounted, kMount_rad, 1e-5);
}

TEST(MountingOffsetTest, TheServoHoldsOnItsEncoderWhileGravityActsOnTheJoint) {
  const RobotModel bench = bench_model();
  ParameterSet v = damped(bench);
  const double plain = final_reading(bench, v, kGoal_rad);
  v.set("joint.pendulum.mounting_offset_rad", kMount_rad);
  const double mounted = final_reading(bench, v, kGoal_rad);
  ParameterSet logged_only = damped(bench);
  logged_only.set("joint.pendulum.encoder_offset_rad", kMount_rad);
  const double shifted = final_reading(bench, logged_only, kGoal_rad);
  const double expected_plain = servo_rest_reading(v, kGoal_rad, 0.0);
  const double expected_mounted = servo_rest_reading(v, kGoal_rad, kMount_rad);
  std::printf(
      "[ servo    ] reading %.6f (equation %.6f) without, %.6f (equation %.6f) with "
      "m; encoder offset alone %.6f\n",
      plain, expected_plain, mounted, expected_mounted, shifted);
  EXPECT_NEAR(plain, expected_plain, 1e-5);
  EXPECT_NEAR(mounted, expected_mounted, 1e-5);
  // The droop changes by M·g·l·cos/(K + M·g·l·cos)·m, a fraction of m; a log offset adds all
  // of it.
  EXPECT_GT(mounted - plain, 0.1 * kMount_rad);
  EXPECT_LT(mounted - plain, 0.5 * kMount_rad);
  EXPECT_NEAR(shifted - plain, kMount_rad, 1e-9);
}

}  // namespace
}  // namespace motoflex
