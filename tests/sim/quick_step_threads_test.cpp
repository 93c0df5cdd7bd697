// dWorldQuickStep in parallel threads: motoflex's dRand (src/sim/ode_thread_random.cpp) gives
// every thread its own copy of ODE's generator, so quick rollouts run side by side without a
// lock and still give the bits they give alone.

#include <gtest/gtest.h>
#include <ode/ode.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/parallel_rollouts.hpp"
#include "motoflex/sim/rollout.hpp"
#include "ode_quick_step.hpp"

namespace motoflex {
namespace {

TEST(QuickStepThreadsTest, LibodeDrawsFromTheThreadsOwnCopyOfItsGenerator) {
  ASSERT_TRUE(detail::ode_random_is_per_thread())
      << "libode binds dRand to its own definition here: quick steps fall back to the lock";

  // ODE's own self-check of its sequence from state 0 (it resets the library's global state,
  // which no longer feeds anything, and draws through dRand): ours is the same generator.
  detail::ode_thread_random_state() = 0;
  EXPECT_EQ(dTestRand(), 1);

  // The draws of another thread leave this thread's state where it is.
  detail::ode_thread_random_state() = 7;
  const unsigned long library_state = dRandGetSeed();
  std::uint32_t other_thread_state = 0;
  std::thread other([&other_thread_state] {
    detail::ode_thread_random_state() = 100;
    for (int i = 0; i < 1000; ++i) static_cast<void>(dRandInt(50));
    other_thread_state = detail::ode_thread_random_state();
  });
  other.join();
  EXPECT_EQ(detail::ode_thread_random_state(), 7u);
  EXPECT_NE(other_thread_state, 100u);
  EXPECT_EQ(dRandGetSeed(), library_state);
}

bool bit_equal(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

TEST(QuickStepThreadsTest, ParallelQuickRolloutsEqualSerialOnes) {
  ScenarioOverrides overrides;
  overrides.duration_s = 0.5;
  Scenario s =
      load_scenario(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/nao_default.yaml", overrides);
  s.rollout.solver = StepSolver::kQuickStep;
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
    ASSERT_EQ(serial[i].end, RolloutEnd::kCompleted) << i << ": " << serial[i].end_detail;
    EXPECT_EQ(serial[i].physics_steps, parallel[i].physics_steps) << i;
    EXPECT_TRUE(bit_equal(serial[i].measured_rad, parallel[i].measured_rad)) << i;
    EXPECT_TRUE(bit_equal(serial[i].torso_position_m, parallel[i].torso_position_m)) << i;
  }
  EXPECT_FALSE(bit_equal(serial[0].measured_rad, serial[3].measured_rad));
}

}  // namespace
}  // namespace motoflex
