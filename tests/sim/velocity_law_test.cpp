// `servo: velocity` (seed 000 eq. 3) on the one-joint turntable: the servo tracks
// θ̇_d = −k_d(θ − θ_d) while its torque suffices (the first-order lag e^{−k_d·t}), and when it
// saturates the joint's Coulomb friction, on its own row beside the servo's, takes exactly F off
// the stall torque: the acceleration is (τ_max − F)/I.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "motoflex/model/parameters.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

using testing::OneJointRobot;

constexpr double kDt_s = 1e-3;
// The arm's CoM on the axis (see pd_torque_law_test.cpp).
const OneJointRobot kTurntable{
    .mass_kg = 0.5, .length_m = 0.0, .com_inertia_kg_m2 = 0.005, .vertical_axis = true};

const RobotModel& turntable() {
  static const RobotModel model =
      testing::make_one_joint_robot("velocity_turntable", kTurntable, "velocity");
  return model;
}

TEST(VelocityLawTest, UnsaturatedServoIsAFirstOrderLag) {
  ParameterSet v(turntable().parameters);
  v.set("joint.hinge.gain_per_s", 4.0);
  v.set("joint.hinge.torque_max_nm", 100.0);
  const auto trace = testing::run_steps(
      turntable(), v, "velocity", 0.0, [](double) { return 0.5; }, 1.0, kDt_s);
  // ODE reaches the asked rate within the step: θ_{k+1} = θ_k + h·k_d·(θ_d − θ_k), i.e.
  // θ_d·(1 − (1 − k_d·h)^k), the discrete form of θ_d·(1 − e^{−k_d·t}).
  for (std::size_t k = 0; k < trace.t_s.size(); k += 100) {
    const double discrete = 0.5 * (1.0 - std::pow(1.0 - 4.0 * kDt_s, static_cast<double>(k + 1)));
    // To the world CFM's softening of the motor row (measured 3.1e-8 rad).
    EXPECT_NEAR(trace.q_rad[k], discrete, 1e-7) << trace.t_s[k];
    EXPECT_NEAR(trace.q_rad[k], 0.5 * (1.0 - std::exp(-4.0 * trace.t_s[k])), 2e-3);
  }
}

TEST(VelocityLawTest, FrictionShiftsTheStallTorqueByExactlyItsValue) {
  const double inertia = axis_inertia_kg_m2(kTurntable);
  const double torque_max = 0.05;
  const auto rate_after = [&](double coulomb) {
    ParameterSet v(turntable().parameters);
    v.set("joint.hinge.gain_per_s", 4.0);  // asks for 20 rad/s: saturated all along
    v.set("joint.hinge.torque_max_nm", torque_max);
    v.set("joint.hinge.friction_nm", coulomb);
    return testing::run_steps(
               turntable(), v, "velocity", -2.5, [](double) { return 2.5; }, 0.3, kDt_s)
        .w_rad_s.back();
  };
  const double free_rate = rate_after(0.0), rubbing_rate = rate_after(0.01);
  std::printf("[ velocity ] ω(0.3 s): %.9f rad/s free, %.9f with F = 0.01 N·m\n", free_rate,
              rubbing_rate);
  EXPECT_NEAR(free_rate, 0.3 * torque_max / inertia, 1e-9);
  EXPECT_NEAR(rubbing_rate, 0.3 * (torque_max - 0.01) / inertia, 1e-9);
}

}  // namespace
}  // namespace motoflex
