// The armature (joint.<J>.armature_kg_m2, reflected rotor inertia) as the rollout's implicit
// joint-space inertia row: a free pendulum swings with the compound-pendulum period
// 2π·√((I + J)/(m·g·l)) under every law that reads it, also when J ≫ I (the row is implicit).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

using testing::kTestGravity_m_s2;
using testing::OneJointRobot;

constexpr double kDt_s = 1e-3;
const OneJointRobot kPendulum{.mass_kg = 0.5, .length_m = 0.1};

// Mean period from downward zero crossings, interpolated between steps.
double measured_period_s(const testing::StepTrace& trace) {
  std::vector<double> crossings;
  for (std::size_t k = 1; k < trace.q_rad.size(); ++k) {
    const double a = trace.q_rad[k - 1], b = trace.q_rad[k];
    if (a > 0.0 && b <= 0.0) crossings.push_back(trace.t_s[k - 1] + kDt_s * a / (a - b));
  }
  if (crossings.size() < 3) return NAN;
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

// The law's drive off, so only gravity, the arm and the armature remain (motoflex: the robot's
// PID gains are 0).
ParameterSet free_arm(const RobotModel& model, double armature_kg_m2) {
  ParameterSet v(model.parameters);
  v.set("joint.hinge.torque_max_nm", 0.0);  // velocity
  v.set("ideal.torque_max_nm", 0.0);        // ideal
  if (v.registry().contains("servo.hinge.kp_nm_per_rad")) v.set("servo.hinge.kp_nm_per_rad", 0.0);
  if (v.registry().contains("servo.hinge.kd_nm_s_per_rad")) {
    v.set("servo.hinge.kd_nm_s_per_rad", 0.0);
  }
  if (v.registry().contains("servo.hinge.Kt_nm_per_a")) v.set("servo.hinge.Kt_nm_per_a", 0.0);
  v.set("joint.hinge.armature_kg_m2", armature_kg_m2);
  return v;
}

TEST(ArmatureTest, SmallAnglePeriodIncludesTheArmatureUnderEveryLaw) {
  const double inertia = axis_inertia_kg_m2(kPendulum);
  const double mgl = kPendulum.mass_kg * kTestGravity_m_s2 * kPendulum.length_m;
  for (const char* law : {"velocity", "ideal", "pd_torque", "dynamixel", "feetech", "motoflex"}) {
    const RobotModel model =
        testing::make_one_joint_robot(std::string("armature_") + law, kPendulum, law);
    // J = 0, J = I (period × √2) and J = 100·I (× √101, J·h/I far beyond an explicit scheme).
    for (const double armature : {0.0, inertia, 100.0 * inertia}) {
      const double expected_s = 2.0 * std::numbers::pi * std::sqrt((inertia + armature) / mgl);
      const auto trace = testing::run_steps(
          model, free_arm(model, armature), law, 0.05, [](double) { return 0.05; },
          5.5 * expected_s, kDt_s);
      const double period_s = measured_period_s(trace);
      std::printf("[ armature ] %-9s J %.6f kg·m²: period %.6f s, analytic %.6f s (%+.2e)\n", law,
                  armature, period_s, expected_s, period_s / expected_s - 1.0);
      // Small-angle error at 0.05 rad: θ₀²/16 = 1.6e-4 (the pendulum's period grows with
      // amplitude); measured +1.5e-4 for every law and J.
      EXPECT_NEAR(period_s / expected_s - 1.0, 1.56e-4, 5e-5) << law << " J " << armature;
    }
  }
}

TEST(ArmatureTest, ArmatureRowEqualsTheSameInertiaInTheArm) {
  // The inertia row against the bench's way (the armature inside the arm's body): the same
  // swing to rounding, at a large amplitude where the motion is far from linear.
  RobotModel model = testing::make_one_joint_robot("armature_bench", kPendulum, "pd_torque");
  constexpr double kArmature = 0.003;
  ParameterSet row = free_arm(model, kArmature - 1e-7);  // the URDF arm has 1e-7
  const auto with_row = testing::run_steps(
      model, row, "pd_torque", 2.0, [](double) { return 2.0; }, 3.0, kDt_s);
  ParameterSet bench(model.parameters);
  bench.set("bench.Kt_nm_per_a", 0.0);
  bench.set("bench.armature_kg_m2", kArmature);
  const auto in_body = testing::run_steps(
      model, bench, "bench", 2.0, [](double) { return 2.0; }, 3.0, kDt_s);
  ASSERT_EQ(with_row.q_rad.size(), in_body.q_rad.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < with_row.q_rad.size(); ++k) {
    worst = std::max(worst, std::abs(with_row.q_rad[k] - in_body.q_rad[k]));
  }
  std::printf("[ armature ] row vs inertia in the body over 3 s from 2 rad: max |Δq| %.2e rad\n",
              worst);
  EXPECT_LT(worst, 3e-11);  // rounding only: measured 8.8e-12 rad
}

}  // namespace
}  // namespace motoflex
