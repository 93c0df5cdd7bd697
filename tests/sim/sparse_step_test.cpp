// Solver `sparse`: dWorldStep with motoflex's LCP solver in place of libode's (src/sim/
// ode_sparse_step.cpp). The same LCP has one solution, so the Nao's motion must agree with
// dWorldStep's to rounding, and every problem must have been solved by motoflex's solver.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "motoflex/sim/rollout.hpp"
#include "ode_sparse_step.hpp"
#include "rollout_ode_access.hpp"

namespace motoflex {
namespace {

TEST(SparseStepTest, LibodeCallsMotoflexsSolverInThisProgram) {
  EXPECT_TRUE(detail::ode_lcp_is_replaced());
}

struct Replay {
  std::vector<double> angles_rad;  // [step × joint]
  std::vector<double> torso_z_m;
  long problems = 0, solved = 0, fallbacks = 0;
  detail::BoxLcpSolver::Counts counts;
};

// The bundled Nao scenario (full MoToFlex servo, flexible links with 2 sub-bodies, 100 gear
// sub-steps; feet on the ground) stepped through its first `seconds` of commands.
Replay replay(const Scenario& s, StepSolver solver, double seconds) {
  RolloutOptions options = s.rollout;
  options.solver = solver;
  const std::size_t n = s.commands.joints();
  std::vector<double> now(n), next(n);
  for (std::size_t j = 0; j < n; ++j) now[j] = s.commands.angle_rad(0, j);
  Rollout rollout(*s.model, s.parameters, options, now);
  Replay out;
  std::size_t hint_now = 0, hint_next = 0;
  const auto steps = static_cast<std::size_t>(std::llround(seconds / options.dt_s));
  for (std::size_t k = 0; k < steps; ++k) {
    const double t = s.commands.start_s() + static_cast<double>(k) * options.dt_s;
    s.commands.sample(t, now.data(), hint_now);
    s.commands.sample(t + options.dt_s, next.data(), hint_next);
    if (!rollout.step(now.data(), next.data())) break;
    for (std::size_t j = 0; j < n; ++j) out.angles_rad.push_back(rollout.joint_angle_rad(j));
    out.torso_z_m.push_back(rollout.torso_position_m().z());
  }
  EXPECT_EQ(rollout.end(), RolloutEnd::kCompleted) << rollout.end_detail();
  const detail::SparseStepState& lcp = RolloutOdeAccess::sparse_lcp(rollout);
  out.problems = lcp.solver.counts().problems;
  out.solved = lcp.solver.counts().solved;
  out.fallbacks = lcp.fallbacks;
  out.counts = lcp.solver.counts();
  return out;
}

TEST(SparseStepTest, NaoMotionAgreesWithDWorldStepToRounding) {
  ScenarioOverrides overrides;
  overrides.duration_s = 1.0;
  const Scenario s =
      load_scenario(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/nao_default.yaml", overrides);
  ASSERT_EQ(s.model->structure.flex_sub_bodies, 2);
  const Replay exact = replay(s, StepSolver::kStep, 1.0);
  const Replay sparse = replay(s, StepSolver::kSparseStep, 1.0);
  ASSERT_EQ(exact.angles_rad.size(), sparse.angles_rad.size());
  ASSERT_EQ(exact.angles_rad.size(), 1000 * s.commands.joints());
  double largest_rad = 0.0, moved_rad = 0.0;
  for (std::size_t k = 0; k < exact.angles_rad.size(); ++k) {
    largest_rad = std::max(largest_rad, std::abs(exact.angles_rad[k] - sparse.angles_rad[k]));
    moved_rad = std::max(moved_rad, std::abs(exact.angles_rad[k] - exact.angles_rad[k % 10]));
  }
  EXPECT_LT(largest_rad, 1e-9);
  EXPECT_GT(moved_rad, 0.05);  // the robot moved: not a trivial agreement
  for (std::size_t k = 0; k < exact.torso_z_m.size(); ++k) {
    EXPECT_NEAR(exact.torso_z_m[k], sparse.torso_z_m[k], 1e-10);
  }
  // dWorldStep never reached motoflex's solver; with `sparse` every LCP did, and none was
  // handed back to libode's.
  EXPECT_EQ(exact.problems, 0);
  EXPECT_GE(sparse.problems, 1000);
  EXPECT_EQ(sparse.solved, sparse.problems);
  EXPECT_EQ(sparse.fallbacks, 0);
  // The warm start holds: two pivot rounds per problem (phase 1 and phase 2) when every guess
  // is right. And the sparse factor is far smaller than the dense triangle.
  const auto& c = sparse.counts;
  const double rounds_per_problem = static_cast<double>(c.pivot_rounds) / c.problems;
  const long dense_entries = c.rows * (c.rows - 1) / 2;
  std::cout << "Nao, flexible legs: " << c.rows << " rows, L has " << c.l_entries << " of "
            << dense_entries << " entries; " << rounds_per_problem << " pivot rounds and "
            << static_cast<double>(c.factor_rows) / c.problems << " factor rows per problem, "
            << c.orderings << " elimination orders for " << c.problems << " problems\n";
  EXPECT_LE(rounds_per_problem, 2.2);
  EXPECT_LT(c.l_entries, dense_entries / 2);
  EXPECT_LT(c.orderings, c.problems / 10);
}

// Every bundled robot (an arm on a table, a servo pendulum, the original program's box Nao, the
// TITAN-VIII quadruped with four feet on the ground) standing for 0.5 s from its stand pose: the
// sparse solver settles every LCP itself and the motion is dWorldStep's to rounding.
TEST(SparseStepTest, EveryBundledRobotGivesDWorldStepsMotion) {
  for (const std::string name : {"mini_arm", "servo_pendulum", "nao_motoflex_2011", "titan8"}) {
    SCOPED_TRACE(name);
    const RobotModel model =
        load_robot(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + name, {});
    const ParameterSet parameters(model.parameters);
    const std::vector<double> pose = model.stand_pose_vector();
    RolloutOptions options;
    options.servo = model.default_servo;
    std::vector<std::vector<double>> angles_rad(2);
    long solved = 0, fallbacks = 0;
    for (const StepSolver solver : {StepSolver::kStep, StepSolver::kSparseStep}) {
      options.solver = solver;
      Rollout rollout(model, parameters, options, pose);
      for (int k = 0; k < 500 && rollout.step(pose.data(), pose.data()); ++k) {
        for (std::size_t j = 0; j < rollout.joints(); ++j) {
          angles_rad[solver == StepSolver::kSparseStep].push_back(rollout.joint_angle_rad(j));
        }
      }
      if (solver == StepSolver::kSparseStep) {
        solved = RolloutOdeAccess::sparse_lcp(rollout).solver.counts().solved;
        fallbacks = RolloutOdeAccess::sparse_lcp(rollout).fallbacks;
      }
    }
    ASSERT_EQ(angles_rad[0].size(), angles_rad[1].size());
    ASSERT_EQ(angles_rad[0].size(), 500 * model.actuators.size());
    for (std::size_t k = 0; k < angles_rad[0].size(); ++k) {
      ASSERT_NEAR(angles_rad[0][k], angles_rad[1][k], 1e-9) << "value " << k;
    }
    EXPECT_EQ(solved, 500);
    EXPECT_EQ(fallbacks, 0);
  }
}

}  // namespace
}  // namespace motoflex
