// A released joint's friction (released_friction.hpp, the effect released_friction): with the
// H-bridge off the joint's Coulomb and viscous levels are the powered ones plus a change.
//  * the change is exact arithmetic, clamped at no friction, and 0 is the powered friction;
//  * a coasting turntable (no gravity, no drive, no back-EMF once released) decelerates at
//    exactly K_c/I under Coulomb friction and decays as e^(−K_v·t/I) under viscous friction;
//  * a released pendulum turns exactly its friction's work into lost height between two swing
//    extremes θ_n, θ_{n+1} (at rest there): m·g·l·(cos θ_{n+1} − cos θ_n) = K_c·(|θ_n| +
//    |θ_{n+1}|).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "bench_stall_support.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/sim/actuator/released_friction.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

using testing::OneJointRobot;

constexpr double kDt_s = 1e-3;

TEST(ReleasedFrictionTest, NeutralIsThePoweredFrictionAndTheChangeIsClamped) {
  FrictionParams powered;
  powered.coulomb_nm = 0.04;
  powered.viscous_nm_s_per_rad = 0.003;
  powered.stribeck_nm = 0.02;
  powered.load_motor = 0.2;
  powered.backdrive = 0.1;
  const FrictionParams same = released_friction(powered, {});
  for (const double v : {0.0, 0.3, -2.0}) {
    for (const double tm : {0.0, 0.5}) {
      EXPECT_EQ(friction_budget_nm(same, v, tm, -0.4), friction_budget_nm(powered, v, tm, -0.4));
    }
  }
  const FrictionParams lower = released_friction(powered, {-0.03, 0.007});
  EXPECT_DOUBLE_EQ(lower.coulomb_nm, 0.01);
  EXPECT_DOUBLE_EQ(lower.viscous_nm_s_per_rad, 0.01);
  EXPECT_EQ(lower.stribeck_nm, powered.stribeck_nm);
  EXPECT_EQ(lower.load_motor, powered.load_motor);
  EXPECT_EQ(lower.backdrive, powered.backdrive);
  const FrictionParams none = released_friction(powered, {-0.2, -0.2});
  EXPECT_EQ(none.coulomb_nm, 0.0);
  EXPECT_EQ(none.viscous_nm_s_per_rad, 0.0);
}

// A heavy turntable (I = 0.18 kg·m², no gravity torque) driven towards a far goal by the
// Dynamixel firmware law and released at 0.1 s.
const OneJointRobot kTurntable{
    .mass_kg = 2.0, .length_m = 0.0, .com_inertia_kg_m2 = 0.18, .vertical_axis = true};

const RobotModel& turntable() {
  static const RobotModel model =
      testing::make_one_joint_robot("released_friction_turntable", kTurntable, "dynamixel");
  return model;
}

testing::StepTrace released_turntable(double coulomb_delta_nm, double viscous_delta) {
  ParameterSet p(turntable().parameters);
  p.set("servo.hinge.torque_off_s", 0.1);
  p.set("joint.hinge.friction_nm", 0.05);
  p.set("joint.hinge.viscous_nm_s_per_rad", 0.0);
  p.set("joint.hinge.released_friction_delta_nm", coulomb_delta_nm);
  p.set("joint.hinge.released_viscous_delta_nm_s_per_rad", viscous_delta);
  return testing::run_steps(
      turntable(), p, "dynamixel", -2.5, [](double) { return 2.5; }, 0.4, kDt_s);
}

TEST(ReleasedFrictionTest, AReleasedTurntableCoastsDownAtTheReleasedLevels) {
  const double inertia_kg_m2 = testing::axis_inertia_kg_m2(kTurntable);
  // Coulomb: ω falls linearly at K_c/I between 0.15 s and 0.35 s (index k is t = (k+1) ms).
  const auto deceleration = [](const testing::StepTrace& trace) {
    return (trace.w_rad_s[149] - trace.w_rad_s[349]) / 0.2;
  };
  const testing::StepTrace powered_level = released_turntable(0.0, 0.0);
  const testing::StepTrace raised = released_turntable(0.1, 0.0);
  ASSERT_GT(powered_level.w_rad_s[349], 0.1);
  ASSERT_GT(raised.w_rad_s[349], 0.1);
  std::printf("[ coulomb ] deceleration %.5f rad/s^2 (K_c/I %.5f), raised %.5f (%.5f)\n",
              deceleration(powered_level), 0.05 / inertia_kg_m2, deceleration(raised),
              0.15 / inertia_kg_m2);
  EXPECT_NEAR(deceleration(powered_level), 0.05 / inertia_kg_m2, 0.005 * 0.05 / inertia_kg_m2);
  EXPECT_NEAR(deceleration(raised), 0.15 / inertia_kg_m2, 0.005 * 0.15 / inertia_kg_m2);
  // Released to no Coulomb friction and a viscous 0.09 N·m·s/rad: ω(t) = ω₀·e^(−K_v·t/I).
  const testing::StepTrace viscous = released_turntable(-0.1, 0.09);
  const double rate_per_s = std::log(viscous.w_rad_s[149] / viscous.w_rad_s[349]) / 0.2;
  std::printf("[ viscous ] decay rate %.5f /s (K_v/I %.5f)\n", rate_per_s, 0.09 / inertia_kg_m2);
  EXPECT_NEAR(rate_per_s, 0.09 / inertia_kg_m2, 0.01 * 0.09 / inertia_kg_m2);
}

// The XL330 bench (bench law, the arm a point mass): held at 0.4 rad for 1.5 s, then released.
struct Extremes {
  std::vector<double> angles_rad;
  double mgl_nm = 0.0;
};

Extremes released_pendulum_extremes(double coulomb_delta_nm) {
  const RobotModel bench = testing::load_servo_pendulum();
  ParameterSet p(bench.parameters);
  p.set("bench.logged_supply", 0.0);
  p.set("bench.torque_off_s", 1.5);
  p.set("joint.pendulum.friction_nm", 0.04);
  p.set("joint.pendulum.viscous_nm_s_per_rad", 0.0);
  p.set("joint.pendulum.released_friction_delta_nm", coulomb_delta_nm);
  const testing::StepTrace trace = testing::run_steps(
      bench, p, "bench", 0.0, [](double) { return 0.4; }, 4.0, kDt_s);
  Extremes out;
  out.mgl_nm = testing::bench_gravity_torque_nm(p);
  // Swing extremes: the release (the arm held still), then where the rate changes sign (the
  // nearer sample to w = 0).
  EXPECT_LT(std::abs(trace.w_rad_s[1499]), 1e-4);
  out.angles_rad.push_back(trace.q_rad[1499]);
  for (std::size_t k = 1501; k + 1 < trace.w_rad_s.size(); ++k) {
    if (trace.w_rad_s[k - 1] * trace.w_rad_s[k] < 0.0) {
      const bool earlier = std::abs(trace.w_rad_s[k - 1]) < std::abs(trace.w_rad_s[k]);
      out.angles_rad.push_back(trace.q_rad[earlier ? k - 1 : k]);
    }
  }
  return out;
}

// K_c from the energy balance of the first `half_swings` half swings.
std::vector<double> coulomb_from_swings(const Extremes& e, std::size_t half_swings) {
  std::vector<double> out;
  for (std::size_t n = 0; n + 1 < e.angles_rad.size() && n < half_swings; ++n) {
    const double a = e.angles_rad[n], b = e.angles_rad[n + 1];
    out.push_back(e.mgl_nm * (std::cos(b) - std::cos(a)) / (std::abs(a) + std::abs(b)));
  }
  return out;
}

TEST(ReleasedFrictionTest, AReleasedPendulumLosesItsHeightToTheReleasedCoulombFriction) {
  const Extremes powered = released_pendulum_extremes(0.0);
  const Extremes released = released_pendulum_extremes(-0.03);
  // K_c 0.04 N·m stops the arm within two half swings; 0.01 N·m lets it swing on for several.
  ASSERT_GE(powered.angles_rad.size(), 2u);
  ASSERT_GE(released.angles_rad.size(), 5u);
  EXPECT_GT(released.angles_rad.size(), powered.angles_rad.size() + 2);
  for (const double f : coulomb_from_swings(powered, 2)) {
    std::printf("[ powered  ] K_c from the swing %.5f N·m (set 0.04)\n", f);
    EXPECT_NEAR(f, 0.04, 0.0004);
  }
  for (const double f : coulomb_from_swings(released, 4)) {
    std::printf("[ released ] K_c from the swing %.5f N·m (set 0.01)\n", f);
    EXPECT_NEAR(f, 0.01, 0.0001);
  }
}

}  // namespace
}  // namespace motoflex
