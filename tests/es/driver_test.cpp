#include "motoflex_es/driver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "test_problems.hpp"

namespace motoflex_es {
namespace {

using testing::BenchmarkProblem;
using testing::Function;

MuPlusLambdaOptions small() {
  MuPlusLambdaOptions options;
  options.mu = 3;
  options.lambda = 7;
  return options;
}

TEST(EsDriverTest, EvaluationBudgetIsNeverExceeded) {
  BenchmarkProblem problem(Function::kSphere, 2);
  MuPlusLambda es(problem.bounds(), small());
  SerialEvaluator evaluator;
  Budget budget;
  budget.max_evaluations = 50;
  const RunSummary summary = run_optimisation(es, problem, evaluator, budget);
  // 3 initial + 6 × 7 = 45; another batch would make 52.
  EXPECT_EQ(summary.reason, RunStopReason::kMaxEvaluations);
  EXPECT_EQ(summary.evaluations, 45u);
  EXPECT_EQ(problem.calls(), 45u);
  EXPECT_EQ(summary.generations, 7u);
}

TEST(EsDriverTest, GenerationBudgetCountsTheWholeRunAcrossResumes) {
  BenchmarkProblem problem(Function::kSphere, 2);
  MuPlusLambda es(problem.bounds(), small());
  SerialEvaluator evaluator;
  Budget budget;
  budget.max_generations = 4;
  RunSummary summary = run_optimisation(es, problem, evaluator, budget);
  EXPECT_EQ(summary.reason, RunStopReason::kMaxGenerations);
  EXPECT_EQ(es.generation(), 4u);
  budget.max_generations = 10;
  summary = run_optimisation(es, problem, evaluator, budget);
  EXPECT_EQ(es.generation(), 10u);
  EXPECT_EQ(summary.generations_this_call, 6u);
  EXPECT_EQ(summary.evaluations_this_call, 6u * 7u);
}

TEST(EsDriverTest, CallbackSeesEveryGenerationAndCanStopTheRun) {
  BenchmarkProblem problem(Function::kSphere, 2);
  MuPlusLambda es(problem.bounds(), small());
  SerialEvaluator evaluator;
  std::vector<GenerationReport> reports;
  RunCallbacks callbacks;
  callbacks.on_generation = [&reports](const Strategy& strategy, const GenerationReport& report) {
    EXPECT_EQ(report.generation, strategy.generation());
    EXPECT_EQ(report.best_fitness, strategy.best_fitness());
    reports.push_back(report);
    return reports.size() < 5;
  };
  const RunSummary summary = run_optimisation(es, problem, evaluator, Budget{}, callbacks);
  EXPECT_EQ(summary.reason, RunStopReason::kCallback);
  ASSERT_EQ(reports.size(), 5u);
  EXPECT_EQ(reports[0].batch_size, 3u);
  EXPECT_EQ(reports[1].batch_size, 7u);
  EXPECT_EQ(reports[0].stop_threshold, std::numeric_limits<double>::infinity());
  EXPECT_LT(reports[1].stop_threshold, std::numeric_limits<double>::infinity());
  for (const auto& report : reports) EXPECT_LE(report.best_fitness, report.batch_best);
  EXPECT_NE(summary.full_report().find("mu_plus_lambda"), std::string::npos);
  EXPECT_NE(summary.brief_report().find("callback"), std::string::npos);
}

TEST(EsDriverTest, ContextCarriesGenerationAndThreshold) {
  class Recording : public BenchmarkProblem {
   public:
    Recording() : BenchmarkProblem(Function::kSphere, 2) {}
    void evaluate_batch(const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                        const EvaluationContext& context) override {
      contexts.push_back(context);
      BenchmarkProblem::evaluate_batch(xs, fitness, context);
    }
    std::vector<EvaluationContext> contexts;
  } problem;
  MuPlusLambda es(problem.bounds(), small());
  std::vector<double> thresholds;
  RunCallbacks callbacks;
  callbacks.on_generation = [&thresholds](const Strategy& strategy, const GenerationReport&) {
    thresholds.push_back(strategy.selection_threshold());
    return true;
  };
  SerialEvaluator evaluator;
  Budget budget;
  budget.max_generations = 6;
  run_optimisation(es, problem, evaluator, budget, callbacks);
  // Generation 0 is the initial population, one batch; every later generation is raced in
  // chunks of μ offspring, the first against the selection threshold, each later one against a
  // bound that only tightens, indices contiguous.
  std::size_t next = 0;
  for (std::uint64_t g = 0; g < 6; ++g) {
    ASSERT_LT(next, problem.contexts.size());
    EXPECT_EQ(problem.contexts[next].generation, g);
    EXPECT_EQ(problem.contexts[next].first_individual, 0u);
    if (g > 0) {
      EXPECT_EQ(problem.contexts[next].stop_threshold, thresholds[g - 1]);
    }
    std::uint64_t covered = small().mu;
    double bound = problem.contexts[next].stop_threshold;
    for (++next; next < problem.contexts.size() && problem.contexts[next].generation == g; ++next) {
      EXPECT_EQ(problem.contexts[next].first_individual, covered);
      EXPECT_LE(problem.contexts[next].stop_threshold, bound);
      bound = problem.contexts[next].stop_threshold;
      covered = std::min<std::uint64_t>(small().lambda, covered + small().mu);
    }
    EXPECT_EQ(covered, g == 0 ? small().mu : small().lambda) << "generation " << g;
  }
  EXPECT_EQ(next, problem.contexts.size());
}

// A refit's incumbent (the model it extends) is evaluated once before the search: the run's best
// can then not be worse than it, and the search itself goes on exactly as without it.
TEST(EsDriverTest, IncumbentBoundsTheBestAndLeavesTheSearchAlone) {
  BenchmarkProblem problem(Function::kSphere, 3);
  CmaEsOptions options;
  options.start_point = {4.0, 4.0, 4.0};
  options.initial_sigma_relative = 0.01;
  options.max_restarts = 0;
  CmaEs with(problem.bounds(), options);
  CmaEs without(problem.bounds(), options);
  std::vector<double> optimum;
  for (std::size_t i = 0; i < 3; ++i) optimum.push_back(testing::optimum_coordinate(i));
  SerialEvaluator evaluator;
  EXPECT_EQ(evaluate_incumbent(with, problem, evaluator, optimum), 0.0);
  Budget budget;
  budget.max_generations = 3;
  const RunSummary a = run_optimisation(with, problem, evaluator, budget);
  const RunSummary b = run_optimisation(without, problem, evaluator, budget);
  // A small step far from the optimum never reaches it in three generations.
  EXPECT_GT(b.best_fitness, 10.0);
  EXPECT_EQ(a.best_fitness, 0.0);
  EXPECT_EQ(a.best_x, optimum);
  EXPECT_EQ(a.evaluations, b.evaluations + 1);
  EXPECT_EQ(with.ask(), without.ask());
  EXPECT_THROW(with.record_incumbent({0.0, 0.0}, 1.0), std::invalid_argument);
  EXPECT_THROW(with.record_incumbent({0.0, 0.0, 9.0}, 1.0), std::invalid_argument);
}

TEST(EsDriverTest, DimensionMismatchIsAnError) {
  BenchmarkProblem problem(Function::kSphere, 3);
  MuPlusLambda es(Bounds{{0.0, 0.0}, {1.0, 1.0}}, small());
  SerialEvaluator evaluator;
  EXPECT_THROW(run_optimisation(es, problem, evaluator, Budget{}), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex_es
