// `servo: pd_torque` on the one-joint turntable (no gravity torque) against closed forms: the
// step response of I·θ̈ = kp·(θ_d − θ) − kd·θ̇, the constant acceleration τ_max/I of a saturated
// drive, the torque–speed curve's exponential approach to the no-load speed, and the friction
// terms (Coulomb, viscous, and BAM's load-dependent M3/M5 on a pendulum).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "motoflex/model/parameters.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

using testing::kTestGravity_m_s2;
using testing::OneJointRobot;

constexpr double kDt_s = 1e-3;
// The arm's CoM on the axis: an offset CoM spinning up loses energy to ODE's constraint
// stabilisation (the centripetal drift corrected by ERP; 1e-4 of ω at 5 rad/s, measured).
const OneJointRobot kTurntable{
    .mass_kg = 0.5, .length_m = 0.0, .com_inertia_kg_m2 = 0.005, .vertical_axis = true};

const RobotModel& turntable() {
  static const RobotModel model =
      testing::make_one_joint_robot("pd_torque_turntable", kTurntable, "pd_torque");
  return model;
}

ParameterSet gains(double kp, double kd, double torque_max, double no_load_speed = 0.0) {
  ParameterSet v(turntable().parameters);
  v.set("servo.hinge.kp_nm_per_rad", kp);
  v.set("servo.hinge.kd_nm_s_per_rad", kd);
  v.set("servo.hinge.torque_max_nm", torque_max);
  v.set("servo.hinge.no_load_speed_rad_s", no_load_speed);
  return v;
}

TEST(PdTorqueLawTest, StepResponseIsTheClosedFormSecondOrderSystem) {
  const double inertia = axis_inertia_kg_m2(kTurntable);
  const double kp = 2.0, kd = 0.02, step = 0.5;
  const double wn = std::sqrt(kp / inertia);                 // 20 rad/s
  const double zeta = kd / (2.0 * std::sqrt(kp * inertia));  // 0.1
  const double wd = wn * std::sqrt(1.0 - zeta * zeta);
  const auto trace = testing::run_steps(
      turntable(), gains(kp, kd, 100.0), "pd_torque", 0.0, [&](double) { return step; }, 2.0,
      kDt_s);
  EXPECT_NEAR(trace.torque_nm.front(), kp * step, 1e-12);
  double worst = 0.0;
  for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
    const double t = trace.t_s[k];
    const double analytic =
        step *
        (1.0 - std::exp(-zeta * wn * t) *
                   (std::cos(wd * t) + zeta / std::sqrt(1.0 - zeta * zeta) * std::sin(wd * t)));
    worst = std::max(worst, std::abs(trace.q_rad[k] - analytic));
  }
  std::printf("[ pd_torque ] step 0.5 rad, ωn 20 rad/s, ζ 0.1: max |q − closed form| %.2e rad\n",
              worst);
  // Explicit PD torque from the step's start state with symplectic Euler: a phase error of order
  // ωn·h per cycle; measured 4.9e-3 rad over 2 s (6 cycles of a 0.5 rad step).
  EXPECT_LT(worst, 1.5e-2);
}

TEST(PdTorqueLawTest, SaturatedDriveAndTorqueSpeedCurve) {
  const double inertia = axis_inertia_kg_m2(kTurntable);
  const double torque_max = 0.05, q0 = -2.5, goal = 2.5;
  // Without a curve: constant acceleration τ_max/I, ω after k steps = k·h·τ_max/I exactly.
  auto trace = testing::run_steps(
      turntable(), gains(1000.0, 0.0, torque_max), "pd_torque", q0, [&](double) { return goal; },
      0.5, kDt_s);
  EXPECT_NEAR(trace.torque_nm.back(), torque_max, 1e-15);
  EXPECT_NEAR(trace.w_rad_s.back(), 0.5 * torque_max / inertia, 1e-9);
  // With the curve: τ = τ_max·(1 − ω/ω₀), so ω(t) = ω₀·(1 − exp(−t·τ_max/(I·ω₀))).
  const double w0 = 5.0;
  trace = testing::run_steps(
      turntable(), gains(1000.0, 0.0, torque_max, w0), "pd_torque", q0,
      [&](double) { return goal; }, 1.0, kDt_s);
  double worst = 0.0;
  for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
    const double analytic = w0 * (1.0 - std::exp(-trace.t_s[k] * torque_max / (inertia * w0)));
    worst = std::max(worst, std::abs(trace.w_rad_s[k] - analytic));
  }
  std::printf("[ pd_torque ] torque-speed curve: max |ω − closed form| %.2e rad/s (ω₀ 5)\n", worst);
  // Forward difference of a 0.5 s time constant at 1 ms: ≤ ω₀·h/(2τ) = 5e-3; measured 1.8e-3.
  EXPECT_LT(worst, 6e-3);
}

TEST(PdTorqueLawTest, CoulombAndViscousFrictionSlowTheSaturatedDrive) {
  const double inertia = axis_inertia_kg_m2(kTurntable);
  const double torque_max = 0.05, coulomb = 0.01, viscous = 0.004;
  ParameterSet v = gains(1000.0, 0.0, torque_max);
  v.set("joint.hinge.friction_nm", coulomb);
  v.set("joint.hinge.viscous_nm_s_per_rad", viscous);
  const auto trace = testing::run_steps(
      turntable(), v, "pd_torque", -2.5, [](double) { return 2.5; }, 0.5, kDt_s);
  // I·ω̇ = τ_max − F − K_v·ω: ω(t) = (τ_max − F)/K_v·(1 − exp(−K_v·t/I)).
  double worst = 0.0;
  for (std::size_t k = 0; k < trace.t_s.size(); ++k) {
    const double analytic =
        (torque_max - coulomb) / viscous * (1.0 - std::exp(-viscous * trace.t_s[k] / inertia));
    worst = std::max(worst, std::abs(trace.w_rad_s[k] - analytic));
  }
  std::printf("[ pd_torque ] Coulomb + viscous drive: max |ω − closed form| %.2e rad/s\n", worst);
  EXPECT_LT(worst, 3e-3);  // measured 1.1e-3 (first-order in h)
  // The friction costs (F + K_v·ω)/I of acceleration: 1.7 of 5.0 rad/s at 0.5 s.
  EXPECT_LT(trace.w_rad_s.back(), 0.5 * torque_max / inertia - 1.5);
}

TEST(PdTorqueLawTest, LoadDependentFrictionReadsTheGravityTorque) {
  // BAM's M3: K_l·|τ_m − τ_e| with τ_m = 0 (no gains) is K_l·m·g·l·sin q on a pendulum: at rest
  // it holds back K_l of the gravity torque. M5's K_e does the same; M1 ignores both.
  const OneJointRobot pendulum{.mass_kg = 0.5, .length_m = 0.1};
  const RobotModel model = testing::make_one_joint_robot("pd_torque_m3", pendulum, "pd_torque");
  const double inertia = axis_inertia_kg_m2(pendulum);
  const double q0 = 0.8, gravity = 0.5 * kTestGravity_m_s2 * 0.1 * std::sin(q0);
  const auto first_rate = [&](double model_number, const char* coefficient) {
    ParameterSet v(model.parameters);
    v.set("servo.hinge.kp_nm_per_rad", 0.0);
    v.set("servo.hinge.kd_nm_s_per_rad", 0.0);
    v.set("joint.hinge.friction_model", model_number);
    v.set(coefficient, 0.5);
    return testing::run_steps(
               model, v, "pd_torque", q0, [&](double) { return q0; }, 0.01, kDt_s)
        .w_rad_s.front();
  };
  // To the world CFM's 5e-8 relative softening of the friction row (law_friction_test.cpp).
  const double tolerance = 1e-6 * gravity;
  EXPECT_NEAR(first_rate(3, "joint.hinge.load_friction") * inertia / kDt_s, -0.5 * gravity,
              tolerance);
  EXPECT_NEAR(first_rate(5, "joint.hinge.load_friction_external") * inertia / kDt_s, -0.5 * gravity,
              tolerance);
  EXPECT_NEAR(first_rate(1, "joint.hinge.load_friction") * inertia / kDt_s, -gravity, tolerance);
}

}  // namespace
}  // namespace motoflex
