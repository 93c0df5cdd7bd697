// The servo pendulum bench as a physics check of the rollout: with the motor torque exactly
// zero the arm is a textbook compound pendulum, I·q̈ = −m·g·l·sin q (+ dry friction), with
// I = m·l² + armature (the loader puts the bench mass as a point at bench.length_m and the
// armature about the joint axis).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;  // the rollout's world gravity
constexpr double kDt_s = 1e-3;
constexpr double kArmature_kg_m2 = 1e-4;  // lower bound of bench.armature_kg_m2

const RobotModel& bench_model() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum", StructureOptions{});
  return model;
}

// A passive bench: motor torque exactly zero, no viscous friction, the smallest armature the
// bounds allow. The bench torque is τ = K_t·U/R − K_t²·θ̇/R, so K_t = 0 removes both the drive
// and the back-EMF braking, exactly (kp = 0 or supply_v = 0 would leave the back-EMF term,
// K_t²/R ≥ 1.7e-3 N·m·s/rad inside the bounds: on the XL330 bench, I = 0.005 kg·m², that still
// damps the energy with a time constant I·R/K_t² ≈ 3 s).
// K_t = 0 is below the search bound 0.1 but is the physical state of a released H-bridge.
ParameterSet passive_bench(double mass_kg, double length_m, double friction_nm = 0.0,
                           double armature_kg_m2 = kArmature_kg_m2) {
  ParameterSet params(bench_model().parameters);
  params.set("bench.Kt_nm_per_a", 0.0);
  params.set("bench.mass_kg", mass_kg);
  params.set("bench.length_m", length_m);
  params.set("bench.armature_kg_m2", armature_kg_m2);
  params.set("joint.pendulum.friction_nm", friction_nm);
  params.set("joint.pendulum.viscous_nm_s_per_rad", 0.0);
  return params;
}

RolloutOptions bench_options() {
  RolloutOptions options;
  options.dt_s = kDt_s;
  options.solver = StepSolver::kStep;
  options.servo = "bench";
  return options;
}

struct Trace {
  std::vector<double> t_s, q_rad, w_rad_s;
};

// Releases the arm at rest from q0 and records the true joint angle and rate after every step.
Trace release(const ParameterSet& params, double q0_rad, double duration_s) {
  Rollout rollout(bench_model(), params, bench_options(), {q0_rad});
  Trace trace;
  trace.t_s.push_back(0.0);
  trace.q_rad.push_back(rollout.joint_angle_rad(0));
  trace.w_rad_s.push_back(rollout.joint_rate_rad_s(0));
  const auto steps = static_cast<int>(std::lround(duration_s / kDt_s));
  for (int k = 0; k < steps; ++k) {
    // The command is irrelevant with K_t = 0; hold the release angle.
    EXPECT_TRUE(rollout.step(&q0_rad, &q0_rad));
    EXPECT_EQ(rollout.actuator_torque_nm(0), 0.0);
    trace.t_s.push_back(rollout.time_s());
    trace.q_rad.push_back(rollout.joint_angle_rad(0));
    trace.w_rad_s.push_back(rollout.joint_rate_rad_s(0));
  }
  return trace;
}

struct Load {
  double mass_kg;
  double length_m;
};
// XL330 and STS3250 benches of the BAM logs, and a long heavy arm.
const Load kLoads[] = {{0.49, 0.1}, {1.13, 0.12}, {2.0, 0.4}};

// dWorldStep is semi-implicit (symplectic) Euler: v₁ = v₀ + h·a(q₀), q₁ = q₀ + h·v₁, so the
// rate read after a step is the mean rate over that step, i.e. the rate half a step earlier
// than the angle it is read with. Pairing them gives an energy that oscillates (without
// drifting) by ≈ h·ω/2 — 0.49 % for the XL330 bench at 1 ms (ω ≈ 9.8 rad/s), 0.54 % measured.
// The energy at step k therefore pairs q_k with the time-centred rate (v_k + v_{k+1})/2, which
// is second-order accurate; the secular drift is checked separately on period means.
TEST(PendulumPhysicsTest, FrictionlessPendulumConservesEnergy) {
  for (const Load& load : kLoads) {
    const double m = load.mass_kg, l = load.length_m;
    const double inertia = m * l * l + kArmature_kg_m2;
    const double mgl = m * kGravity_m_s2 * l;
    const Trace trace = release(passive_bench(m, l), 0.5, 10.0);
    ASSERT_NEAR(trace.q_rad.front(), 0.5, 1e-12);
    auto energy = [&](double q, double w) {
      return mgl * (1.0 - std::cos(q)) + 0.5 * inertia * w * w;
    };
    const double e0 = energy(trace.q_rad[0], 0.0);
    const std::size_t n = trace.t_s.size();
    double worst = 0.0, worst_staggered = 0.0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double w = 0.5 * (trace.w_rad_s[k] + trace.w_rad_s[k + 1]);
      worst = std::max(worst, std::abs(energy(trace.q_rad[k], w) - e0) / e0);
      worst_staggered =
          std::max(worst_staggered, std::abs(energy(trace.q_rad[k], trace.w_rad_s[k]) - e0) / e0);
    }
    // Mean energy over the first and the last period: the oscillation averages out.
    const double period_s = 2.0 * std::numbers::pi * std::sqrt(inertia / mgl);
    const auto per = static_cast<std::size_t>(period_s / kDt_s);
    double first = 0.0, last = 0.0;
    for (std::size_t k = 0; k < per; ++k) {
      first += energy(trace.q_rad[k], trace.w_rad_s[k]) / static_cast<double>(per);
      last += energy(trace.q_rad[n - 1 - k], trace.w_rad_s[n - 1 - k]) / static_cast<double>(per);
    }
    const double drift = (last - first) / e0;
    std::printf(
        "[ energy  ] m %.2f kg, l %.2f m: max |ΔE|/E %.4f %% (staggered read %.4f %%, "
        "h·ω/2 %.4f %%), drift over 10 s %+.4f %%\n",
        m, l, 100.0 * worst, 100.0 * worst_staggered,
        100.0 * 0.5 * kDt_s * std::sqrt(mgl / inertia), 100.0 * drift);
    EXPECT_LT(worst, 0.005) << "m " << m << " l " << l;
    EXPECT_LT(std::abs(drift), 0.001) << "m " << m << " l " << l;
    // And it really swung: the arm passes through the bottom and reaches the far side.
    EXPECT_LT(*std::min_element(trace.q_rad.begin(), trace.q_rad.end()), -0.49);
  }
}

TEST(PendulumPhysicsTest, SmallAnglePeriodMatchesCompoundPendulum) {
  for (const Load& load : kLoads) {
    const double m = load.mass_kg, l = load.length_m;
    const double inertia = m * l * l + kArmature_kg_m2;
    const double period_s = 2.0 * std::numbers::pi * std::sqrt(inertia / (m * kGravity_m_s2 * l));
    const Trace trace = release(passive_bench(m, l), 0.05, 10.5 * period_s);
    // Downward zero crossings, linearly interpolated between steps.
    std::vector<double> crossings;
    for (std::size_t k = 1; k < trace.t_s.size(); ++k) {
      const double a = trace.q_rad[k - 1], b = trace.q_rad[k];
      if (a > 0.0 && b <= 0.0) {
        crossings.push_back(trace.t_s[k - 1] + (trace.t_s[k] - trace.t_s[k - 1]) * a / (a - b));
      }
    }
    ASSERT_GE(crossings.size(), 10u);
    const double measured_s =
        (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    const double error = measured_s / period_s - 1.0;
    std::printf("[ period  ] m %.2f kg, l %.2f m: T %.6f s, analytic %.6f s, error %+.4f %%\n", m,
                l, measured_s, period_s, 100.0 * error);
    EXPECT_LT(std::abs(error), 0.005) << "m " << m << " l " << l;
  }
}

TEST(PendulumPhysicsTest, DryFrictionHoldsBelowTheBreakawayTorque) {
  const double m = 0.49, l = 0.1, friction_nm = 0.3;
  const double max_gravity_nm = m * kGravity_m_s2 * l;  // 0.48 N·m
  // Gravity torques of 50 % and 95 % of the friction budget, on either side.
  for (const double fraction : {0.5, 0.95, -0.95}) {
    const double q0 = std::asin(fraction * friction_nm / max_gravity_nm);
    const Trace trace = release(passive_bench(m, l, friction_nm), q0, 1.0);
    double drift = 0.0;
    for (const double q : trace.q_rad) drift = std::max(drift, std::abs(q - q0));
    EXPECT_LT(drift, 1e-6) << "τ_g/F = " << fraction << ", drift " << drift << " rad";
  }
}

TEST(PendulumPhysicsTest, DryFrictionSlipsWithReducedAcceleration) {
  // Arm near horizontal, where sin q is flat, and a large armature so that the gravity torque
  // hardly changes over 0.2 s: q(t) ≈ q0 − ½·(τ_g − F)/I·t². The Euler step itself adds
  // h/t = +0.5 % (ODE moves by the end-of-step rate: ½·α·h²·N(N+1) after N steps).
  const double m = 0.49, l = 0.1, armature = 0.05;
  const double inertia = m * l * l + armature;
  const double max_gravity_nm = m * kGravity_m_s2 * l;
  // The last budget is 95 % of the gravity torque: just past breakaway.
  for (const double friction_nm : {0.0, 0.2, 0.35, 0.4565}) {
    const double q0 = std::numbers::pi / 2 + 0.03;  // swings down through the horizontal
    const Trace trace = release(passive_bench(m, l, friction_nm, armature), q0, 0.2);
    const double gravity_nm = max_gravity_nm * std::sin(q0);
    const double alpha = (gravity_nm - friction_nm) / inertia;
    const double expected_drop = 0.5 * alpha * 0.2 * 0.2;
    const double drop = q0 - trace.q_rad.back();
    std::printf(
        "[ slip    ] F %.4f N·m: drop %.6f rad, constant-acceleration %.6f rad (%+.3f %%)\n",
        friction_nm, drop, expected_drop, 100.0 * (drop / expected_drop - 1.0));
    EXPECT_NEAR(drop, expected_drop, 0.02 * expected_drop) << "F " << friction_nm;
    // The rate at the end is α·t as well.
    EXPECT_NEAR(-trace.w_rad_s.back(), alpha * 0.2, 0.02 * alpha * 0.2) << "F " << friction_nm;
  }
}

}  // namespace
}  // namespace motoflex
