// physics.float_state: every body's stored state rounded to single precision after each step,
// as the 2011 program's float build of ODE keeps it (motoflex_2011.md §1). The rounding must
// really happen (each stored component a float afterwards, and not without the option), and it
// must not change the physics beyond float resolution: on the passive XL330 bench the arm
// swings as a frictionless pendulum, energy conserved as with double state.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "motoflex/sim/rollout.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;  // the rollout's world gravity
constexpr double kDt_s = 1e-3;
constexpr double kMass_kg = 0.49;
constexpr double kLength_m = 0.1;
constexpr double kArmature_kg_m2 = 1e-4;

const RobotModel& bench_model() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum", StructureOptions{});
  return model;
}

// The bench with the motor off (K_t = 0: no drive, no back-EMF) and no friction.
ParameterSet passive_bench() {
  ParameterSet params(bench_model().parameters);
  params.set("bench.Kt_nm_per_a", 0.0);
  params.set("bench.mass_kg", kMass_kg);
  params.set("bench.length_m", kLength_m);
  params.set("bench.armature_kg_m2", kArmature_kg_m2);
  params.set("joint.pendulum.friction_nm", 0.0);
  params.set("joint.pendulum.viscous_nm_s_per_rad", 0.0);
  return params;
}

RolloutOptions options(bool float_state) {
  RolloutOptions out;
  out.dt_s = kDt_s;
  out.solver = StepSolver::kStep;
  out.servo = "bench";
  out.float_state = float_state;
  return out;
}

bool is_float(double value) {
  return static_cast<double>(static_cast<float>(value)) == value;
}

// How many of the moving bodies' stored position and velocity components are not floats.
int non_float_components(const Rollout& rollout) {
  int count = 0;
  for (std::size_t b = 0; b < bench_model().bodies.size(); ++b) {
    const dBodyID body = RolloutOdeAccess::body(rollout, b);
    if (body == nullptr) continue;
    for (const dReal* v :
         {dBodyGetPosition(body), dBodyGetLinearVel(body), dBodyGetAngularVel(body)}) {
      for (int i = 0; i < 3; ++i) count += is_float(v[i]) ? 0 : 1;
    }
  }
  return count;
}

struct Swing {
  std::vector<double> q_rad, w_rad_s;
  int non_float_steps = 0;  // steps after which some stored component was not a float
};

Swing release(bool float_state, double q0_rad, double duration_s) {
  Rollout rollout(bench_model(), passive_bench(), options(float_state), {q0_rad});
  Swing swing;
  const auto steps = static_cast<int>(std::lround(duration_s / kDt_s));
  for (int k = 0; k < steps; ++k) {
    EXPECT_TRUE(rollout.step(&q0_rad, &q0_rad));
    swing.q_rad.push_back(rollout.joint_angle_rad(0));
    swing.w_rad_s.push_back(rollout.joint_rate_rad_s(0));
    if (non_float_components(rollout) > 0) ++swing.non_float_steps;
  }
  return swing;
}

TEST(FloatState, EveryStoredComponentIsAFloatAfterEachStep) {
  const Swing rounded = release(true, 0.5, 0.2);
  EXPECT_EQ(rounded.non_float_steps, 0);
  // Without the option the double state is kept: almost every step leaves non-float digits.
  const Swing exact = release(false, 0.5, 0.2);
  EXPECT_GT(exact.non_float_steps, 150);
}

TEST(FloatState, PendulumSwingsAsWithDoubleStateToFloatResolution) {
  const double duration_s = 3.0;
  const Swing rounded = release(true, 0.5, duration_s);
  const Swing exact = release(false, 0.5, duration_s);
  ASSERT_EQ(rounded.q_rad.size(), exact.q_rad.size());
  double worst_gap_rad = 0.0;
  for (std::size_t k = 0; k < exact.q_rad.size(); ++k) {
    worst_gap_rad = std::max(worst_gap_rad, std::abs(rounded.q_rad[k] - exact.q_rad[k]));
  }
  // A float holds the arm's position (0.1 m) to 4e-9 m, 4e-8 rad; over 3000 steps of a
  // non-chaotic swing the rounding adds up to far less than a microradian per step.
  EXPECT_GT(worst_gap_rad, 0.0);
  EXPECT_LT(worst_gap_rad, 1e-4);
  // Energy with the time-centred rate (pendulum_physics_test.cpp): conserved as with doubles.
  const double inertia = kMass_kg * kLength_m * kLength_m + kArmature_kg_m2;
  const double mgl = kMass_kg * kGravity_m_s2 * kLength_m;
  const double e0 = mgl * (1.0 - std::cos(0.5));
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < rounded.q_rad.size(); ++k) {
    const double w = 0.5 * (rounded.w_rad_s[k] + rounded.w_rad_s[k + 1]);
    const double e = mgl * (1.0 - std::cos(rounded.q_rad[k])) + 0.5 * inertia * w * w;
    worst = std::max(worst, std::abs(e - e0) / e0);
  }
  EXPECT_LT(worst, 0.005);
}

}  // namespace
}  // namespace motoflex
