// FitnessFunction::evaluate with several threads simulates a parameter set's logs in parallel
// when nothing can stop early: the breakdown and every rollout equal the serial ones bit for bit.

#include <gtest/gtest.h>

#include <limits>

#include "fit_test_support.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex::testing {
namespace {

TEST(FitnessParallel, TheLogsOfOneEvaluationOnTwoThreadsGiveTheSerialResult) {
  const std::string fit = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/fit/bench_hidden.yaml";
  const FitConfig config = load_fit_config(fit);  // two training logs
  ASSERT_EQ(config.train->cases().size(), 2u);
  const ParameterSet set = config.space->apply(config.space->start());
  const double never = std::numeric_limits<double>::infinity();
  std::vector<RolloutResult> serial, parallel;
  const FitnessBreakdown a = config.train->evaluate(set, never, &serial, 1);
  const FitnessBreakdown b = config.train->evaluate(set, never, &parallel, 2);
  ASSERT_TRUE(std::isfinite(a.fitness));
  EXPECT_EQ(a.fitness, b.fitness);
  ASSERT_EQ(b.cases.size(), 2u);
  ASSERT_EQ(parallel.size(), 2u);
  for (std::size_t c = 0; c < 2; ++c) {
    EXPECT_EQ(a.cases[c].fitness, b.cases[c].fitness);
    EXPECT_EQ(a.cases[c].frames, b.cases[c].frames);
    EXPECT_EQ(serial[c].measured_rad, parallel[c].measured_rad);
  }
  // The two logs differ, so a mix-up of cases would show.
  EXPECT_NE(a.cases[0].fitness, a.cases[1].fitness);
}

}  // namespace
}  // namespace motoflex::testing
