// `servo: bench` with a PD firmware: duty = g·kp·(e + T_d·ė), T_d = bench.derivative_s. Near
// the hanging rest pose the arm is a linear oscillator,
//   J·θ̈ + (b + K_t²/R + K·T_d)·θ̇ + (K + m·g·l)·θ = K·θ_d,   K = K_t·U·g·kp/R,
// J = armature + m·l², so after a small step of the goal its oscillation decays as e^(−σt) with
// σ = (b + K_t²/R + K·T_d)/(2J): the D term adds exactly K·T_d of damping, and nothing to the
// rest pose.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "bench_stall_support.hpp"
#include "motoflex/core/line_fit.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"

namespace motoflex::testing {
namespace {

const RobotModel& bench() {
  static const RobotModel model = load_servo_pendulum();
  return model;
}

constexpr double kStepGoal_rad = 0.05;  // small: the duty stays below 1, sin q ≈ q
constexpr double kRamp_s = 0.01;        // the goal's step, spread over one 100 Hz sample

ParameterSet pd_bench(double derivative_s) {
  ParameterSet v = stall_bench_values(bench());
  v.set("bench.derivative_s", derivative_s);
  return v;
}

RolloutResult step_response(const ParameterSet& v) {
  const CommandTrajectory command = keyframe_trajectory(
      {{0.0, {0.0}}, {0.1, {0.0}}, {0.1 + kRamp_s, {kStepGoal_rad}}, {4.0, {kStepGoal_rad}}},
      100.0);
  RolloutOptions options;
  options.servo = "bench";
  return run_rollout(bench(), v, command, options);
}

// K = K_t·U·g·kp/R (N·m per rad of error), J = armature + m·l² (kg·m²).
double servo_stiffness_nm_per_rad(const ParameterSet& v) {
  return v.get("bench.Kt_nm_per_a") * v.get("bench.supply_v") * v.get("bench.error_gain") *
         v.get("bench.kp") / v.get("bench.R_ohm");
}
double arm_inertia_kg_m2(const ParameterSet& v) {
  return v.get("bench.armature_kg_m2") +
         v.get("bench.mass_kg") * v.get("bench.length_m") * v.get("bench.length_m");
}

// The decay rate σ (1/s) of |θ − θ_rest| from its peaks after the step: the slope of a
// least-squares line through (t, ln |peak|).
double decay_rate_per_s(const RolloutResult& r, double rest_rad) {
  std::vector<double> t_s;
  std::vector<double> log_amplitude;
  for (std::size_t f = 1; f + 1 < r.measured_rad.size(); ++f) {
    const double a = r.measured_rad[f - 1] - rest_rad;
    const double b = r.measured_rad[f] - rest_rad;
    const double c = r.measured_rad[f + 1] - rest_rad;
    const bool peak = std::abs(b) >= std::abs(a) && std::abs(b) > std::abs(c) && a * c > 0.0;
    if (r.time_s[f] > 0.1 + 2.0 * kRamp_s && peak && std::abs(b) > 1e-5) {
      t_s.push_back(r.time_s[f]);
      log_amplitude.push_back(std::log(std::abs(b)));
    }
  }
  EXPECT_GE(t_s.size(), 4u) << "too few peaks to measure a decay";
  return -fit_line(t_s, log_amplitude, true).slope;
}

TEST(BenchDerivative, TheDTermAddsExactlyItsDampingAndNothingToTheRestPose) {
  for (const double derivative_s : {0.0, 0.01, 0.02}) {
    const ParameterSet v = pd_bench(derivative_s);
    const RolloutResult r = step_response(v);
    ASSERT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
    const double k = servo_stiffness_nm_per_rad(v);
    const double j = arm_inertia_kg_m2(v);
    // K·(θ_d − θ) = m·g·l·sin θ, by Newton from the linear answer.
    const double mgl = bench_gravity_torque_nm(v);
    double rest_rad = k * kStepGoal_rad / (k + mgl);
    for (int i = 0; i < 5; ++i) {
      rest_rad -= (mgl * std::sin(rest_rad) - k * (kStepGoal_rad - rest_rad)) /
                  (mgl * std::cos(rest_rad) + k);
    }
    // The rest pose does not depend on T_d (ė = 0 there).
    EXPECT_NEAR(r.measured_rad.back(), rest_rad, 1e-6) << derivative_s;
    const double kt = v.get("bench.Kt_nm_per_a");
    const double damping = v.get("joint.pendulum.viscous_nm_s_per_rad") +
                           kt * kt / v.get("bench.R_ohm") + k * derivative_s;
    EXPECT_NEAR(decay_rate_per_s(r, rest_rad), damping / (2.0 * j), 0.03 * damping / (2.0 * j))
        << "T_d " << derivative_s << " s";
  }
}

TEST(BenchDerivative, TheDutyAddsTdTimesTheErrorRate) {
  BenchServoParams p;
  p.kp = 10.0;
  p.error_gain = 0.01;
  p.supply_v = 8.0;
  p.torque_constant_nm_per_a = 0.5;
  p.resistance_ohm = 2.0;
  p.derivative_s = 0.02;
  // e = 0.1 rad, ė = 1 − 0.25 rad/s: duty = 0.1·(0.1 + 0.02·0.75) = 0.0115.
  const double torque_nm = bench_servo_output(p, 0.1, 0.0, 0.25, true, 1.0).torque_nm;
  EXPECT_NEAR(torque_nm, 0.5 * 8.0 * 0.0115 / 2.0 - 0.25 * 0.25 / 2.0, 1e-12);
  // T_d = 0: the P law, whatever the goal's rate.
  p.derivative_s = 0.0;
  EXPECT_EQ(bench_servo_output(p, 0.1, 0.0, 0.25, true, 1.0).torque_nm,
            bench_servo_output(p, 0.1, 0.0, 0.25, true).torque_nm);
}

TEST(BenchDerivative, ANegativeDerivativeTimeIsAModelError) {
  const RolloutResult r = hold_bench(bench(), pd_bench(-0.01), 0.0, 0.1);
  EXPECT_EQ(r.end, RolloutEnd::kModelError);
  EXPECT_NE(r.end_detail.find("bench.derivative_s"), std::string::npos) << r.end_detail;
}

}  // namespace
}  // namespace motoflex::testing
