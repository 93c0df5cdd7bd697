// A rollout is a pure function of (model, parameters, commands, options): the same run twice,
// or many runs spread over threads, give bit-identical logs (DESIGN.md, "Determinism").

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/parallel_rollouts.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

// The bundled Nao scenario: full motoflex pipeline, flex 2, 100 gear sub-steps, 0.5 s settle;
// cut to 1 s of its squat so the suite stays fast.
Scenario nao_scenario() {
  ScenarioOverrides overrides;
  overrides.duration_s = 1.0;
  Scenario scenario =
      load_scenario(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/nao_default.yaml", overrides);
  scenario.parameters.set("sensor.noise_rad", 1e-3);
  scenario.parameters.set("sensor.resolution_bits", 12);
  return scenario;
}

bool bit_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

void expect_bit_identical(const RolloutResult& a, const RolloutResult& b, const std::string& what) {
  EXPECT_EQ(a.end, b.end) << what;
  EXPECT_EQ(a.frames_completed, b.frames_completed) << what;
  EXPECT_EQ(a.physics_steps, b.physics_steps) << what;
  EXPECT_TRUE(bit_equal(a.measured_rad, b.measured_rad)) << what << ": measured_rad";
  EXPECT_TRUE(bit_equal(a.imu_roll_rad, b.imu_roll_rad)) << what << ": imu_roll_rad";
  EXPECT_TRUE(bit_equal(a.imu_pitch_rad, b.imu_pitch_rad)) << what << ": imu_pitch_rad";
  EXPECT_TRUE(bit_equal(a.torso_position_m, b.torso_position_m)) << what << ": torso";
}

TEST(DeterminismTest, SameRolloutTwiceIsBitIdentical) {
  const Scenario s = nao_scenario();
  ASSERT_EQ(s.rollout.servo, "motoflex");
  ASSERT_EQ(s.model->structure.flex_sub_bodies, 2);
  ASSERT_EQ(s.rollout.gear_substeps, 100);
  ASSERT_EQ(s.rollout.solver, StepSolver::kStep);
  const RolloutResult first = run_rollout(*s.model, s.parameters, s.commands, s.rollout);
  const RolloutResult second = run_rollout(*s.model, s.parameters, s.commands, s.rollout);
  ASSERT_EQ(first.end, RolloutEnd::kCompleted) << first.end_detail;
  ASSERT_EQ(first.frames_completed, s.commands.frames());
  expect_bit_identical(first, second, "repeat");

  // The noise is really on, and only the sensor sees it: another seed changes the readings
  // but not the motion (the servos regulate on the true angle).
  RolloutOptions other_seed = s.rollout;
  other_seed.seed = 2;
  const RolloutResult third = run_rollout(*s.model, s.parameters, s.commands, other_seed);
  EXPECT_FALSE(bit_equal(first.measured_rad, third.measured_rad));
  EXPECT_TRUE(bit_equal(first.torso_position_m, third.torso_position_m));
}

// With either solver: QuickStep's row order comes from a generator each thread owns
// (src/sim/ode_thread_random.cpp), so its parallel rollouts give their serial bits too.
void expect_parallel_equal_to_serial(StepSolver solver, const std::string& what) {
  Scenario s = nao_scenario();
  s.rollout.solver = solver;
  std::vector<ParameterSet> params(4, s.parameters);
  const double resistances_ohm[] = {6.44, 5.0, 8.0, 12.0};
  for (std::size_t i = 0; i < params.size(); ++i) params[i].set("motor.R_ohm", resistances_ohm[i]);
  std::vector<RolloutJob> jobs;
  for (const ParameterSet& p : params) jobs.push_back({s.model.get(), &p, &s.commands, s.rollout});

  std::vector<RolloutResult> serial;
  for (const RolloutJob& job : jobs) {
    serial.push_back(run_rollout(*job.model, *job.parameters, *job.commands, job.options));
  }
  const std::vector<RolloutResult> parallel = run_rollouts(jobs, 2);
  ASSERT_EQ(parallel.size(), serial.size());
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    ASSERT_EQ(serial[i].end, RolloutEnd::kCompleted) << what << i << ": " << serial[i].end_detail;
    expect_bit_identical(serial[i], parallel[i], what + " job " + std::to_string(i));
  }
  // Different parameters do give different runs (the comparison above is not vacuous).
  EXPECT_FALSE(bit_equal(serial[0].measured_rad, serial[3].measured_rad)) << what;
}

TEST(DeterminismTest, ParallelRolloutsEqualSerialOnes) {
  expect_parallel_equal_to_serial(StepSolver::kStep, "step");
}

// Solver `sparse`: each rollout owns its LCP solver and warm start (src/sim/ode_sparse_step.cpp).
TEST(DeterminismTest, ParallelSparseStepRolloutsEqualSerialOnes) {
  expect_parallel_equal_to_serial(StepSolver::kSparseStep, "sparse");
}

TEST(DeterminismTest, ParallelQuickStepRolloutsEqualSerialOnes) {
  expect_parallel_equal_to_serial(StepSolver::kQuickStep, "quick");
}

}  // namespace
}  // namespace motoflex
