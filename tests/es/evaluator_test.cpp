#include "motoflex_es/evaluator.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "motoflex_es/random.hpp"
#include "test_problems.hpp"

namespace motoflex_es {
namespace {

// Rastrigin plus noise drawn from a stream keyed by (generation, individual): correct only if
// every evaluator hands each individual its own index.
class NoisyRastrigin : public Problem {
 public:
  std::size_t dimension() const override { return 6; }
  Bounds bounds() const override {
    return Bounds{std::vector<double>(6, -5.0), std::vector<double>(6, 5.0)};
  }
  void evaluate_batch(const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                      const EvaluationContext& context) override {
    for (std::size_t k = 0; k < xs.size(); ++k) {
      motoflex::RandomStream noise =
          es_stream(99, context.generation, context.first_individual + k, Purpose::kTest);
      fitness[k] =
          testing::benchmark(testing::Function::kRastrigin, xs[k]) + 0.1 * noise.normal_libm();
    }
  }
};

std::string run_to_end(Strategy& strategy, Evaluator& evaluator) {
  NoisyRastrigin problem;
  Budget budget;
  budget.max_generations = 40;
  run_optimisation(strategy, problem, evaluator, budget);
  return strategy.save_state().dump();
}

TEST(EsEvaluatorTest, OneAndTwoThreadsGiveBitIdenticalRuns) {
  const Bounds bounds = NoisyRastrigin().bounds();
  MuPlusLambdaOptions es_options;
  es_options.mu = 5;
  es_options.lambda = 60;
  CmaEsOptions cma_options;
  cma_options.population_size = 24;

  SerialEvaluator serial;
  OpenMpEvaluator one(1);
  OpenMpEvaluator two(2);
  EXPECT_EQ(two.workers(), 2);
  EXPECT_EQ(two.name(), "openmp(2 threads)");

  MuPlusLambda es_serial(bounds, es_options), es_one(bounds, es_options),
      es_two(bounds, es_options);
  const std::string reference = run_to_end(es_serial, serial);
  EXPECT_EQ(run_to_end(es_one, one), reference);
  EXPECT_EQ(run_to_end(es_two, two), reference);

  CmaEs cma_serial(bounds, cma_options), cma_one(bounds, cma_options), cma_two(bounds, cma_options);
  const std::string cma_reference = run_to_end(cma_serial, serial);
  EXPECT_EQ(run_to_end(cma_one, one), cma_reference);
  EXPECT_EQ(run_to_end(cma_two, two), cma_reference);
}

// Throws for every individual whose first coordinate is negative.
class ThrowingProblem : public Problem {
 public:
  std::size_t dimension() const override { return 1; }
  Bounds bounds() const override { return Bounds{{-1.0}, {1.0}}; }
  void evaluate_batch(const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                      const EvaluationContext& context) override {
    for (std::size_t k = 0; k < xs.size(); ++k) {
      if (xs[k][0] < 0.0) {
        throw std::runtime_error("individual " + std::to_string(context.first_individual + k));
      }
      fitness[k] = xs[k][0];
    }
  }
};

TEST(EsEvaluatorTest, TheLowestIndexExceptionReachesTheCaller) {
  ThrowingProblem problem;
  const std::vector<std::vector<double>> xs = {{0.5}, {0.2}, {-0.1}, {0.3}, {-0.7}, {-0.2}};
  std::vector<double> fitness;
  for (int threads : {1, 2, 3}) {
    OpenMpEvaluator evaluator(threads);
    try {
      evaluator.evaluate(problem, xs, fitness, EvaluationContext{});
      FAIL() << "no exception";
    } catch (const std::runtime_error& error) {
      EXPECT_STREQ(error.what(), "individual 2");
    }
  }
  OpenMpEvaluator evaluator(2);
  evaluator.evaluate(problem, {{0.5}, {0.25}}, fitness, EvaluationContext{});
  EXPECT_EQ(fitness, (std::vector<double>{0.5, 0.25}));
}

}  // namespace
}  // namespace motoflex_es
