// Joint friction acts under every law that lists it (velocity, pd_torque, dynamixel, feetech,
// bench, motoflex; README "Servo laws"). Each law is set to apply no motor torque at all, and a
// pendulum is released from rest at q0 on the one-joint robot:
//  * Coulomb F below the gravity torque: the first step's acceleration is (τ_g − F)/I, i.e.
//    friction shifts the torque by exactly F;
//  * F above the gravity torque: the arm sticks;
//  * viscous K_v: the swing matches an RK4 solution of I·q̈ = −m·g·l·sin q − K_v·q̇.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "motoflex/model/parameters.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

using testing::kTestGravity_m_s2;
using testing::OneJointRobot;
using testing::StepTrace;

constexpr double kDt_s = 1e-3;
constexpr double kQ0_rad = 0.8;

const OneJointRobot kPendulum{.mass_kg = 0.5, .length_m = 0.1};

// The law with its drive switched off (and what it then leaves of the arm's inertia).
struct PassiveLaw {
  std::string law;
  RobotModel model;
  double inertia_kg_m2;
};

PassiveLaw passive(const std::string& law) {
  RobotModel model = testing::make_one_joint_robot("friction_" + law, kPendulum, law);
  // bench: the arm is its point mass plus bench.armature_kg_m2 (1e-4); the others keep the
  // URDF arm (1e-7 about its CoM).
  const double inertia = law == "bench" ? 0.5 * 0.1 * 0.1 + 1e-4 : axis_inertia_kg_m2(kPendulum);
  return {law, std::move(model), inertia};
}

ParameterSet passive_values(const PassiveLaw& p, double coulomb_nm, double viscous) {
  ParameterSet v(p.model.parameters);
  if (p.law == "velocity") v.set("joint.hinge.torque_max_nm", 0.0);  // no servo row force
  if (p.law == "pd_torque") {
    v.set("servo.hinge.kp_nm_per_rad", 0.0);
    v.set("servo.hinge.kd_nm_s_per_rad", 0.0);
  }
  if (p.law == "dynamixel" || p.law == "feetech") v.set("servo.hinge.Kt_nm_per_a", 0.0);
  if (p.law == "bench") v.set("bench.Kt_nm_per_a", 0.0);  // motoflex: the PID gains are 0
  v.set("joint.hinge.friction_nm", coulomb_nm);
  v.set("joint.hinge.viscous_nm_s_per_rad", viscous);
  return v;
}

StepTrace release(const PassiveLaw& p, const ParameterSet& values, double duration_s) {
  return testing::run_steps(
      p.model, values, p.law, kQ0_rad, [](double) { return kQ0_rad; }, duration_s, kDt_s);
}

const char* const kLaws[] = {"velocity", "pd_torque", "dynamixel", "feetech", "bench", "motoflex"};

TEST(LawFrictionTest, CoulombFrictionShiftsTheTorqueByExactlyItsValue) {
  const double gravity_nm = 0.5 * kTestGravity_m_s2 * 0.1 * std::sin(kQ0_rad);  // 0.352 N·m
  for (const char* law : kLaws) {
    const PassiveLaw p = passive(law);
    const StepTrace free = release(p, passive_values(p, 0.0, 0.0), 0.05);
    const double friction_nm = 0.4 * gravity_nm;
    const StepTrace held = release(p, passive_values(p, friction_nm, 0.0), 0.05);
    ASSERT_FALSE(free.w_rad_s.empty()) << law;
    // The law applies no torque (velocity: its row has no force; NaN = acts through the row),
    // and gravity alone accelerates the arm: I·ω₁/h = −τ_g.
    if (!std::isnan(free.torque_nm.front())) {
      EXPECT_NEAR(free.torque_nm.front(), 0.0, 1e-12) << law;
    }
    EXPECT_NEAR(p.inertia_kg_m2 * free.w_rad_s.front() / kDt_s, -gravity_nm, 1e-9) << law;
    // With friction the first step's torque is short by exactly F (the budget at rest).
    const double shift_nm = p.inertia_kg_m2 * (held.w_rad_s.front() - free.w_rad_s.front()) / kDt_s;
    std::printf("[ friction ] %-9s torque shift %.12f N·m for F = %.12f N·m\n", law, shift_nm,
                friction_nm);
    // To the world CFM (1e-10): it softens the rows by CFM/(h·J·M⁻¹·Jᵀ), 5e-8 relative here.
    EXPECT_NEAR(shift_nm, friction_nm, 1e-6 * friction_nm) << law;
    // Above the gravity torque the arm sticks.
    const StepTrace stuck = release(p, passive_values(p, 1.2 * gravity_nm, 0.0), 0.3);
    EXPECT_NEAR(stuck.q_rad.back(), kQ0_rad, 1e-9) << law;
  }
}

// I·q̈ = −m·g·l·sin q − K_v·q̇, classic RK4 at 0.1 ms (independent of ODE).
double rk4_viscous_swing(double inertia, double viscous, double duration_s) {
  const double mgl = 0.5 * kTestGravity_m_s2 * 0.1;
  const auto accel = [&](double q, double w) {
    return (-mgl * std::sin(q) - viscous * w) / inertia;
  };
  double q = kQ0_rad, w = 0.0;
  const double h = 1e-4;
  for (long k = 0; k < std::lround(duration_s / h); ++k) {
    const double k1q = w, k1w = accel(q, w);
    const double k2q = w + 0.5 * h * k1w, k2w = accel(q + 0.5 * h * k1q, w + 0.5 * h * k1w);
    const double k3q = w + 0.5 * h * k2w, k3w = accel(q + 0.5 * h * k2q, w + 0.5 * h * k2w);
    const double k4q = w + h * k3w, k4w = accel(q + h * k3q, w + h * k3w);
    q += h / 6.0 * (k1q + 2.0 * k2q + 2.0 * k3q + k4q);
    w += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
  }
  return q;
}

TEST(LawFrictionTest, ViscousFrictionDampsTheSwingAsTheOdeSays) {
  constexpr double kViscous = 0.004;  // N·m·s/rad: decay time 2I/K_v ≈ 2.5 s
  constexpr double kDuration_s = 2.0;
  for (const char* law : kLaws) {
    const PassiveLaw p = passive(law);
    const double expected = rk4_viscous_swing(p.inertia_kg_m2, kViscous, kDuration_s);
    const double undamped = rk4_viscous_swing(p.inertia_kg_m2, 0.0, kDuration_s);
    const StepTrace trace = release(p, passive_values(p, 0.0, kViscous), kDuration_s);
    const double error = std::abs(trace.q_rad.back() - expected);
    std::printf("[ viscous  ] %-9s q(2 s) %.6f rad, RK4 %.6f (undamped %.6f), |error| %.2e rad\n",
                law, trace.q_rad.back(), expected, undamped, error);
    // Semi-implicit Euler at 1 ms with the budget from the step's start rate: measured
    // 1.6e-3 rad (bench: 1.1e-3), against a damping effect of 0.48 rad.
    EXPECT_LT(error, 6e-3) << law;
    EXPECT_GT(std::abs(expected - undamped), 30.0 * 6e-3);
  }
}

TEST(LawFrictionTest, BenchM3LoadFrictionReadsTheGravityTorque) {
  // BAM's M3 on the bench: budget K_c + K_l·|τ_m − τ_e| with τ_m = 0 (K_t = 0) and τ_e the
  // gravity torque m·g·l·sin q0 = 0.352 N·m. K_c = 0.5·τ_g alone lets the arm fall; with
  // K_l = 0.6 the budget is 1.1·τ_g and the arm sticks. Under M1 the same K_l is ignored.
  const double gravity_nm = 0.5 * kTestGravity_m_s2 * 0.1 * std::sin(kQ0_rad);
  const PassiveLaw p = passive("bench");
  ParameterSet v = passive_values(p, 0.5 * gravity_nm, 0.0);
  v.set("joint.hinge.load_friction", 0.6);
  v.set("joint.hinge.friction_model", 3.0);
  const StepTrace m3 = release(p, v, 0.3);
  v.set("joint.hinge.friction_model", 1.0);
  const StepTrace m1 = release(p, v, 0.3);
  std::printf("[ bench M3 ] q(0.3 s): M3 %.9f rad, M1 %.6f rad (start %.1f)\n", m3.q_rad.back(),
              m1.q_rad.back(), kQ0_rad);
  EXPECT_NEAR(m3.q_rad.back(), kQ0_rad, 1e-9);  // stuck
  // Falls under M1: I·q̈ = −0.5·τ_g gives 0.5·0.5·τ_g/I·t² ≈ 0.3 rad by 0.3 s (less as sin q
  // shrinks); measured below.
  EXPECT_LT(m1.q_rad.back(), kQ0_rad - 0.1);
}

TEST(LawFrictionTest, BenchBackdriveLossHoldsTheArmYetTheMotorLiftsIt) {
  // The gear's back-driving loss K_bs·|τ_e| (friction_family.hpp) on the bench, τ_g = 0.352 N·m
  // at q0 and the command 1 rad above q0 (full duty, so τ_m = K_t·U/R at standstill):
  //  * τ_m = 0.5·τ_g: the load drives; K_bs = 0.9 gives a budget 0.9·τ_g > 0.5·τ_g: it holds;
  //  * τ_m = 1.5·τ_g: the motor drives, the loss is off, and the arm lifts.
  //  * BAM's M5 with K_e = 0.9 instead holds the arm in both cases (|K_m·τ_m − K_e·τ_e| ≥
  //    0.9·τ_g > 0.5·τ_g): it cannot hold an arm with little drive and still lift it.
  const double gravity_nm = 0.5 * kTestGravity_m_s2 * 0.1 * std::sin(kQ0_rad);
  RobotModel model = testing::make_one_joint_robot("friction_backdrive", kPendulum, "bench");
  const auto run = [&](double drive_over_gravity, bool backdrive) {
    ParameterSet v(model.parameters);
    const double volts = v.get("bench.supply_v");
    const double ohm = v.get("bench.R_ohm");
    v.set("bench.Kt_nm_per_a", drive_over_gravity * gravity_nm * ohm / volts);
    v.set(
        backdrive ? "joint.hinge.backdrive_friction_static" : "joint.hinge.load_friction_external",
        0.9);
    return testing::run_steps(
        model, v, "bench", kQ0_rad, [](double) { return kQ0_rad + 1.0; }, 0.3, kDt_s);
  };
  const double held = run(0.5, true).q_rad.back();
  const double lifted = run(1.5, true).q_rad.back();
  const double m5_lift = run(1.5, false).q_rad.back();
  std::printf("[ backdrive ] q(0.3 s) - q0: held %.2e, lifted %.4f, M5 %.2e rad\n", held - kQ0_rad,
              lifted - kQ0_rad, m5_lift - kQ0_rad);
  EXPECT_NEAR(held, kQ0_rad, 1e-6);
  // Net 0.5·τ_g on I = 0.0051 kg·m² lifts ~0.3 rad in 0.3 s (less as sin q grows): well clear.
  EXPECT_GT(lifted, kQ0_rad + 0.1);
  EXPECT_NEAR(m5_lift, kQ0_rad, 1e-6);
}

}  // namespace
}  // namespace motoflex
