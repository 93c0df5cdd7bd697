// `servo: bench` drives from the supply voltage the log carries (supply_v column): held against
// gravity at full duty with no dry friction, the arm settles where the stall torque K_t·U/R equals
// m·g·l·sin q, so the hold angle follows the logged supply, not the nominal bench.supply_v;
// bench.logged_supply 0 restores the nominal one.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;  // the rollout's world gravity

const RobotModel& pendulum() {
  static const RobotModel model = load_robot_model(
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/servo_pendulum", StructureOptions{});
  return model;
}

ParameterSet without_dry_friction(double kt_nm_per_a, double r_ohm) {
  ParameterSet p(pendulum().parameters);
  p.set("joint.pendulum.friction_nm", 0.0);
  // Viscous damping settles the arm; it does not move the hold angle.
  p.set("joint.pendulum.viscous_nm_s_per_rad", 0.05);
  p.set("bench.Kt_nm_per_a", kt_nm_per_a);
  p.set("bench.R_ohm", r_ohm);
  p.set("bench.supply_v", 7.4);
  return p;
}

// The goal is straight up (far beyond what the motor can lift): the duty saturates at 1.
CommandTrajectory goal_up(double seconds, const std::vector<double>* supply_v) {
  std::vector<double> t, q;
  for (int k = 0; k * 0.005 <= seconds + 1e-9; ++k) {
    t.push_back(0.005 * k);
    q.push_back(std::numbers::pi);
  }
  CommandTrajectory commands(t, q, 1);
  if (supply_v != nullptr) commands.set_supply_v(std::vector<double>(t.size(), supply_v->front()));
  return commands;
}

double hold_angle_rad(const ParameterSet& p, const CommandTrajectory& commands) {
  RolloutOptions options;
  options.servo = "bench";
  const RolloutResult result = run_rollout(pendulum(), p, commands, options);
  EXPECT_EQ(result.frames_completed, result.frames_requested);
  return result.measured_rad.back();
}

TEST(BenchLoggedSupply, HoldAngleFollowsTheLoggedSupply) {
  const double kt = 0.1, r = 2.6;  // stall torque 0.15-0.28 N·m against m·g·l = 0.48 N·m
  const ParameterSet p = without_dry_friction(kt, r);
  const double m = p.get("bench.mass_kg"), l = p.get("bench.length_m");
  for (const double supply_v : {4.0, 5.0, 6.0}) {
    const std::vector<double> logged{supply_v};
    // Damping ratio ~0.4 about the hold angle: settled well within 10 s.
    const double q = hold_angle_rad(p, goal_up(10.0, &logged));
    const double expected = std::asin(kt * supply_v / r / (m * kGravity_m_s2 * l));
    EXPECT_NEAR(std::abs(q), expected, 2e-3) << supply_v << " V";
  }
  // Without a logged supply, and with the switch off, the nominal 7.4 V holds it.
  const double nominal = std::asin(kt * 7.4 / r / (m * kGravity_m_s2 * l));
  EXPECT_NEAR(std::abs(hold_angle_rad(p, goal_up(10.0, nullptr))), nominal, 2e-3);
  ParameterSet off = p;
  off.set("bench.logged_supply", 0.0);
  const std::vector<double> logged{5.0};
  EXPECT_NEAR(std::abs(hold_angle_rad(off, goal_up(10.0, &logged))), nominal, 2e-3);
}

TEST(BenchLoggedSupply, SwitchMustBeZeroOrOne) {
  ParameterSet p = without_dry_friction(0.1, 2.6);
  p.set("bench.logged_supply", 0.5);
  RolloutOptions options;
  options.servo = "bench";
  const RolloutResult result = run_rollout(pendulum(), p, goal_up(0.1, nullptr), options);
  EXPECT_EQ(result.end, RolloutEnd::kModelError);
  EXPECT_NE(result.end_detail.find("bench.logged_supply"), std::string::npos) << result.end_detail;
}

}  // namespace
}  // namespace motoflex
