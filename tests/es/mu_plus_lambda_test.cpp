#include "motoflex_es/mu_plus_lambda.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "test_problems.hpp"

namespace motoflex_es {
namespace {

using testing::BenchmarkProblem;
using testing::Function;

Bounds box(std::size_t n, double lower = -5.0, double upper = 5.0) {
  return Bounds{std::vector<double>(n, lower), std::vector<double>(n, upper)};
}

// One generation through the interface, evaluating with the benchmark directly.
std::vector<std::vector<double>> step(Strategy& strategy, Function function) {
  std::vector<std::vector<double>> xs = strategy.ask();
  std::vector<double> fitness;
  for (const auto& x : xs) fitness.push_back(testing::benchmark(function, x));
  strategy.tell(fitness);
  return xs;
}

TEST(EsMuPlusLambdaTest, DefaultsAreSeed001sTenPlusEightHundredWithLifetimeThree) {
  const MuPlusLambdaOptions options;
  EXPECT_EQ(options.mu, 10u);
  EXPECT_EQ(options.lambda, 800u);
  EXPECT_EQ(options.kappa, 3u);
  std::string why;
  EXPECT_TRUE(options.is_valid(&why)) << why;
  const MuPlusLambda es(box(16), options);
  EXPECT_DOUBLE_EQ(es.tau_global(), 1.0 / std::sqrt(32.0));  // 1/√(2n)
  EXPECT_DOUBLE_EQ(es.tau_local(), 1.0 / std::sqrt(8.0));    // 1/√(2√n)
}

TEST(EsMuPlusLambdaTest, InvalidOptionsSayWhy) {
  const auto reason = [](MuPlusLambdaOptions options) {
    std::string why;
    EXPECT_FALSE(options.is_valid(&why));
    return why;
  };
  MuPlusLambdaOptions options;
  options.lambda = 5;
  EXPECT_NE(reason(options).find("lambda"), std::string::npos);
  options = {};
  options.kappa = 0;
  EXPECT_NE(reason(options).find("kappa"), std::string::npos);
  options = {};
  options.rho = 11;
  EXPECT_NE(reason(options).find("rho"), std::string::npos);
  options = {};
  options.step_floor_relative = 0.0;
  EXPECT_NE(reason(options).find("step_floor"), std::string::npos);
  options = {};
  options.start_point = {0.0, 9.0};
  EXPECT_THROW(MuPlusLambda(box(2), options), std::invalid_argument);  // outside the bounds
  options.start_point = {0.0};
  EXPECT_THROW(MuPlusLambda(box(2), options), std::invalid_argument);  // wrong size
}

TEST(EsMuPlusLambdaTest, InitialPopulationStartsAtTheStartPointAndAskIsRepeatable) {
  MuPlusLambdaOptions options;
  options.mu = 4;
  options.lambda = 20;
  options.start_point = {1.0, -2.0, 3.0};
  MuPlusLambda es(box(3), options);
  EXPECT_EQ(es.next_batch_size(), 4u);
  const auto first = es.ask();
  ASSERT_EQ(first.size(), 4u);
  EXPECT_EQ(first[0], options.start_point);
  EXPECT_EQ(es.ask(), first);  // ask is a pure function of the state
  std::vector<double> fitness(4, 1.0);
  es.tell(fitness);
  EXPECT_EQ(es.next_batch_size(), 20u);
  EXPECT_EQ(es.ask(), es.ask());
  EXPECT_THROW(es.tell(std::vector<double>(3, 0.0)), std::logic_error);
}

TEST(EsMuPlusLambdaTest, OffspringStayInBoundsAndStepSizesWithinFloorAndCeiling) {
  MuPlusLambdaOptions options;
  options.mu = 5;
  options.lambda = 50;
  options.initial_step_relative = 0.5;  // big steps: many samples leave the box and reflect
  options.step_floor_relative = 1e-3;
  options.step_ceiling_relative = 0.6;
  const Bounds bounds{{0.0, -1.0, 100.0}, {1.0, 1.0, 300.0}};
  MuPlusLambda es(bounds, options);
  for (int g = 0; g < 30; ++g) {
    for (const auto& x : es.ask()) ASSERT_TRUE(bounds.contains(x));
    std::vector<double> fitness;
    for (const auto& x : es.ask()) fitness.push_back(std::abs(x[0] - 1.0) + x[1] * x[1]);
    es.tell(fitness);
    for (const Individual& parent : es.population()) {
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_GE(parent.step[i], 1e-3 * bounds.width(i) * (1 - 1e-12));
        EXPECT_LE(parent.step[i], 0.6 * bounds.width(i) * (1 + 1e-12));
      }
    }
  }
}

// Checks the age bookkeeping of one selection: a parent of age a > 1 was a parent of age a−1
// before, one of age 1 is an offspring of the batch just told; nobody is older than κ.
void expect_ages_consistent(const std::vector<Individual>& before,
                            const std::vector<std::vector<double>>& batch,
                            const std::vector<Individual>& after, std::uint64_t kappa) {
  for (const Individual& survivor : after) {
    ASSERT_GE(survivor.age, 1u);
    ASSERT_LE(survivor.age, kappa);
    if (survivor.age == 1) {
      EXPECT_NE(std::find(batch.begin(), batch.end(), survivor.x), batch.end());
    } else {
      const auto previous = std::find_if(before.begin(), before.end(), [&](const Individual& p) {
        return p.x == survivor.x && p.step == survivor.step;
      });
      ASSERT_NE(previous, before.end());
      EXPECT_EQ(previous->age + 1, survivor.age);
      EXPECT_LT(previous->age, kappa);  // only parents younger than κ competed
    }
  }
}

TEST(EsMuPlusLambdaTest, NoSurvivorIsOlderThanKappa) {
  MuPlusLambdaOptions options;
  options.mu = 5;
  options.lambda = 30;
  options.kappa = 3;
  options.seed = 3;
  MuPlusLambda es(box(4), options);
  step(es, Function::kRastrigin);
  std::uint64_t oldest = 0;
  for (int g = 0; g < 200; ++g) {
    const std::vector<Individual> before = es.population();
    const auto batch = step(es, Function::kRastrigin);
    expect_ages_consistent(before, batch, es.population(), 3);
    for (const Individual& parent : es.population()) oldest = std::max(oldest, parent.age);
  }
  EXPECT_EQ(oldest, 3u);  // the limit was reached, and never passed
}

TEST(EsMuPlusLambdaTest, KappaOneIsCommaSelection) {
  MuPlusLambdaOptions options;
  options.mu = 5;
  options.lambda = 30;
  options.kappa = 1;
  MuPlusLambda es(box(4), options);
  step(es, Function::kSphere);
  bool got_worse = false;
  for (int g = 0; g < 100; ++g) {
    const double parent_best = es.population().front().fitness;
    const auto batch = step(es, Function::kSphere);
    for (const Individual& parent : es.population()) {
      EXPECT_EQ(parent.age, 1u);
      EXPECT_NE(std::find(batch.begin(), batch.end(), parent.x), batch.end());
    }
    got_worse = got_worse || es.population().front().fitness > parent_best;
    EXPECT_EQ(es.selection_threshold(), std::numeric_limits<double>::infinity());
  }
  EXPECT_TRUE(got_worse);  // parents never survive, so the population may lose its best
}

TEST(EsMuPlusLambdaTest, UnlimitedKappaIsPlusSelectionAndKeepsTheBestEver) {
  MuPlusLambdaOptions options;
  options.mu = 5;
  options.lambda = 30;
  options.kappa = kUnlimitedLifetime;
  MuPlusLambda es(box(4), options);
  step(es, Function::kRastrigin);
  std::uint64_t oldest = 0;
  for (int g = 0; g < 150; ++g) {
    const double previous_best = es.population().front().fitness;
    const std::vector<Individual> before = es.population();
    const auto batch = step(es, Function::kRastrigin);
    expect_ages_consistent(before, batch, es.population(), kUnlimitedLifetime);
    EXPECT_LE(es.population().front().fitness, previous_best);
    EXPECT_EQ(es.population().front().fitness, es.best_fitness());
    EXPECT_EQ(es.population().front().x, es.best_x());
    for (const Individual& parent : es.population()) oldest = std::max(oldest, parent.age);
  }
  EXPECT_GT(oldest, 3u);  // an elite lives on
}

struct EsBenchmarkCase {
  Function function;
  double target;
  std::uint64_t budget;
};

// (10+800)-ES, κ = 3, ρ = 2 (defaults), uniform start in [-5, 5]^10, seeds 1–3. Measured
// evaluations to target over seeds 1–6: sphere 1e-8: 34k–40k; ellipsoid 1e-8: 54k–66k;
// Rosenbrock 1: 109k–171k (0.1: 210k–282k; 1e-8 takes ~1.1M); Rastrigin 10: 14k–20k (the best
// reached in 2M evaluations was 3–5: this ES with n step sizes does not find the global basin).
TEST(EsMuPlusLambdaTest, ReachesTargetsOnBenchmarksIn10D) {
  const EsBenchmarkCase cases[] = {
      {Function::kSphere, 1e-8, 60000},
      {Function::kEllipsoid, 1e-8, 100000},
      {Function::kRosenbrock, 1.0, 250000},
      {Function::kRastrigin, 10.0, 40000},
  };
  for (const EsBenchmarkCase& c : cases) {
    for (std::uint64_t seed = 1; seed <= (c.function == Function::kRosenbrock ? 1u : 3u); ++seed) {
      BenchmarkProblem problem(c.function, 10);
      MuPlusLambdaOptions options;
      options.seed = seed;
      MuPlusLambda es(problem.bounds(), options);
      const auto result = testing::run_to_target(es, problem, c.target, c.budget);
      EXPECT_TRUE(result.reached) << testing::to_string(c.function) << " seed " << seed << ": best "
                                  << result.best << " after " << result.evaluations
                                  << " evaluations";
    }
  }
}

TEST(EsMuPlusLambdaTest, TargetAndStagnationStopTheStrategy) {
  BenchmarkProblem problem(Function::kSphere, 3);
  MuPlusLambdaOptions options;
  options.mu = 3;
  options.lambda = 30;
  options.target_fitness = 1e-3;
  MuPlusLambda es(problem.bounds(), options);
  SerialEvaluator evaluator;
  run_optimisation(es, problem, evaluator, Budget{});
  EXPECT_EQ(es.stop_reason(), StopReason::kTargetReached);
  EXPECT_LE(es.best_fitness(), 1e-3);
  EXPECT_TRUE(es.ask().empty());
  EXPECT_EQ(es.next_batch_size(), 0u);

  MuPlusLambdaOptions stagnating;
  stagnating.mu = 3;
  stagnating.lambda = 30;
  stagnating.max_stagnation_generations = 10;
  MuPlusLambda stuck(box(3), stagnating);
  step(stuck, Function::kSphere);
  for (int g = 0; g < 10; ++g) {
    ASSERT_FALSE(stuck.should_stop());
    stuck.ask();
    stuck.tell(std::vector<double>(30, 1e9));  // a plateau far above the initial best
  }
  EXPECT_EQ(stuck.stop_reason(), StopReason::kStagnation);
}

// Runs `first` generations, saves, loads into a fresh strategy through a JSON text round trip,
// and runs `second` more; the result must equal an uninterrupted run bit for bit.
TEST(EsMuPlusLambdaTest, SaveLoadContinueIsBitIdentical) {
  MuPlusLambdaOptions options;
  options.mu = 6;
  options.lambda = 40;
  options.kappa = 3;
  options.rho = 3;
  options.object_recombination = Recombination::kIntermediate;
  options.step_recombination = Recombination::kDiscrete;
  options.seed = 77;
  const Bounds bounds = box(5);

  MuPlusLambda uninterrupted(bounds, options);
  for (int g = 0; g < 25; ++g) step(uninterrupted, Function::kRastrigin);

  MuPlusLambda first(bounds, options);
  for (int g = 0; g < 11; ++g) step(first, Function::kRastrigin);
  first.ask();  // an outstanding ask is not part of the state
  const std::string saved = first.save_state().dump();
  MuPlusLambda resumed(bounds, options);
  resumed.load_state(nlohmann::json::parse(saved));
  EXPECT_EQ(resumed.save_state().dump(), saved);
  for (int g = 11; g < 25; ++g) step(resumed, Function::kRastrigin);

  EXPECT_EQ(resumed.save_state().dump(), uninterrupted.save_state().dump());
  EXPECT_EQ(resumed.best_x(), uninterrupted.best_x());
  EXPECT_EQ(resumed.best_fitness(), uninterrupted.best_fitness());
  EXPECT_EQ(resumed.evaluations(), uninterrupted.evaluations());
}

}  // namespace
}  // namespace motoflex_es
