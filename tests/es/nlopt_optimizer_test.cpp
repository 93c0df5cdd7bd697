#include "motoflex_es/nlopt_optimizer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "motoflex_es/checkpoint.hpp"
#include "test_problems.hpp"

namespace motoflex_es {
namespace {

using testing::BenchmarkProblem;
using testing::Function;

struct NloptCase {
  NloptAlgorithm algorithm;
  Function function;
  double target;
  std::uint64_t budget;
};

// 10-D, start point (3, …, 3) (local algorithms), seed 1. Measured evaluations to target
// (seeds 1–3 for the global algorithms):
//   BOBYQA: sphere 1e-8: 25; ellipsoid 1e-8: 62; Rosenbrock 0.1: 788; Rastrigin: converges to
//           the local minimum next to the start (f = 59.7) after 251 evaluations.
//   SBPLX:  sphere 1e-8: 609; ellipsoid 1e-8: 977; Rosenbrock 0.1: 12.6k; Rastrigin 10: 158.
//   CRS2_LM: sphere 1e-8: 6.3k–6.9k; ellipsoid 1e-8: 8.7k–9.6k; Rosenbrock 10: 2.4k–2.9k;
//            Rastrigin 10: 3.6k–8.9k (best in 20k evaluations: 2–6).
//   ISRES:  sphere 10: 2.3k–3.8k (1: 12.3k–12.7k); ellipsoid: 330–910 after 20k;
//           Rosenbrock 100: 13.6k–15.7k; Rastrigin 100: 84–106 (32–48 after 20k).
//   ESCH:   sphere 1: 1.3k–2.0k; ellipsoid: 221–582 after 20k; Rosenbrock 10: 3.3k–5.0k;
//           Rastrigin 10: 1.3k–2.4k.
// ISRES and ESCH are weak on ill-conditioned problems; they are here as baselines.
TEST(EsNloptTest, ReachesTargetsOnBenchmarksIn10D) {
  const NloptCase cases[] = {
      {NloptAlgorithm::kBobyqa, Function::kSphere, 1e-8, 100},
      {NloptAlgorithm::kBobyqa, Function::kEllipsoid, 1e-8, 200},
      {NloptAlgorithm::kBobyqa, Function::kRosenbrock, 0.1, 2000},
      {NloptAlgorithm::kSbplx, Function::kSphere, 1e-8, 1500},
      {NloptAlgorithm::kSbplx, Function::kEllipsoid, 1e-8, 2500},
      {NloptAlgorithm::kSbplx, Function::kRosenbrock, 0.1, 25000},
      {NloptAlgorithm::kSbplx, Function::kRastrigin, 10.0, 1000},
      {NloptAlgorithm::kCrs2Lm, Function::kSphere, 1e-8, 10000},
      {NloptAlgorithm::kCrs2Lm, Function::kEllipsoid, 1e-8, 15000},
      {NloptAlgorithm::kCrs2Lm, Function::kRosenbrock, 10.0, 5000},
      {NloptAlgorithm::kCrs2Lm, Function::kRastrigin, 10.0, 15000},
      {NloptAlgorithm::kIsres, Function::kSphere, 10.0, 6000},
      {NloptAlgorithm::kIsres, Function::kEllipsoid, 2000.0, 20000},
      {NloptAlgorithm::kIsres, Function::kRosenbrock, 100.0, 20000},
      {NloptAlgorithm::kIsres, Function::kRastrigin, 100.0, 1000},
      {NloptAlgorithm::kEsch, Function::kSphere, 1.0, 4000},
      {NloptAlgorithm::kEsch, Function::kEllipsoid, 2000.0, 20000},
      {NloptAlgorithm::kEsch, Function::kRosenbrock, 10.0, 8000},
      {NloptAlgorithm::kEsch, Function::kRastrigin, 10.0, 4000},
  };
  for (const NloptCase& c : cases) {
    BenchmarkProblem problem(c.function, 10);
    NloptOptions options;
    options.algorithm = c.algorithm;
    options.start_point = std::vector<double>(10, 3.0);
    options.max_evaluations = c.budget;
    NloptOptimizer optimizer(problem.bounds(), options);
    const auto result = testing::run_to_target(optimizer, problem, c.target, c.budget);
    EXPECT_TRUE(result.reached) << to_string(c.algorithm) << " on "
                                << testing::to_string(c.function) << ": best " << result.best
                                << " after " << result.evaluations << " evaluations";
  }
}

TEST(EsNloptTest, BobyqaConvergesToTheLocalMinimumOfRastrigin) {
  BenchmarkProblem problem(Function::kRastrigin, 10);
  NloptOptions options;
  options.start_point = std::vector<double>(10, 3.0);
  NloptOptimizer optimizer(problem.bounds(), options);
  testing::run_serially(optimizer, problem, 1000);
  EXPECT_EQ(optimizer.stop_reason(), StopReason::kOptimizerConverged) << optimizer.stop_detail();
  EXPECT_LT(optimizer.evaluations(), 1000u);
  EXPECT_LT(optimizer.best_fitness(),
            testing::benchmark(Function::kRastrigin, options.start_point));
}

// A global algorithm cut off by its evaluation limit has not converged, and says so: NLopt
// calls MAXEVAL_REACHED a success, which a fit summary must not report as convergence.
TEST(EsNloptTest, AnEvaluationLimitIsNotReportedAsConvergence) {
  BenchmarkProblem problem(Function::kRastrigin, 10);
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kCrs2Lm;
  options.max_evaluations = 300;
  NloptOptimizer optimizer(problem.bounds(), options);
  testing::run_serially(optimizer, problem, 1000);
  EXPECT_EQ(optimizer.stop_reason(), StopReason::kEvaluationBudget) << optimizer.stop_detail();
  EXPECT_EQ(optimizer.evaluations(), 300u);
  EXPECT_EQ(optimizer.stop_detail(), "NLopt: maxeval reached");
}

TEST(EsNloptTest, PolishesAPointToHighAccuracy) {
  BenchmarkProblem problem(Function::kEllipsoid, 10);
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kBobyqa;
  options.initial_step_relative = 0.01;
  for (std::size_t i = 0; i < 10; ++i) {
    options.start_point.push_back(testing::optimum_coordinate(i) + 0.05);
  }
  NloptOptimizer polish(problem.bounds(), options);
  SerialEvaluator evaluator;
  const RunSummary summary = run_optimisation(polish, problem, evaluator, Budget{});
  EXPECT_EQ(summary.reason, RunStopReason::kStrategy);
  EXPECT_LT(polish.best_fitness(), 1e-12);
}

TEST(EsNloptTest, SameSeedSameRunDifferentSeedDifferentRun) {
  const auto run = [](NloptAlgorithm algorithm, std::uint64_t seed) {
    BenchmarkProblem problem(Function::kRastrigin, 10);
    NloptOptions options;
    options.algorithm = algorithm;
    options.max_evaluations = 2000;
    options.seed = seed;
    NloptOptimizer optimizer(problem.bounds(), options);
    SerialEvaluator evaluator;
    run_optimisation(optimizer, problem, evaluator, Budget{});
    EXPECT_EQ(optimizer.evaluations(), 2000u);
    return std::make_pair(optimizer.best_fitness(), optimizer.best_x());
  };
  for (NloptAlgorithm algorithm :
       {NloptAlgorithm::kCrs2Lm, NloptAlgorithm::kIsres, NloptAlgorithm::kEsch}) {
    EXPECT_EQ(run(algorithm, 7), run(algorithm, 7)) << to_string(algorithm);
    EXPECT_NE(run(algorithm, 7).second, run(algorithm, 8).second) << to_string(algorithm);
  }
}

TEST(EsNloptTest, StopsCleanlyWhenDestroyedMidRun) {
  BenchmarkProblem problem(Function::kSphere, 4);
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kCrs2Lm;
  options.max_evaluations = 100000;
  {
    NloptOptimizer optimizer(problem.bounds(), options);
    testing::run_serially(optimizer, problem, 50);
    EXPECT_EQ(optimizer.evaluations(), 50u);
    EXPECT_FALSE(optimizer.should_stop());
    EXPECT_EQ(optimizer.ask().size(), 1u);  // NLopt is waiting inside its objective
  }  // the destructor forces NLopt to stop and joins its thread
  { NloptOptimizer never_started(problem.bounds(), options); }
  SUCCEED();
}

TEST(EsNloptTest, CannotResumeAndSaysSo) {
  NloptOptimizer optimizer(Bounds{{0.0, 0.0}, {1.0, 1.0}}, NloptOptions{});
  EXPECT_FALSE(optimizer.can_resume());
  const nlohmann::json state = optimizer.save_state();
  EXPECT_EQ(state.at("strategy"), "nlopt_bobyqa");
  EXPECT_THROW(optimizer.load_state(state), CheckpointError);
}

TEST(EsNloptTest, GlobalAlgorithmsNeedAnEvaluationLimit) {
  NloptOptions options;
  options.algorithm = NloptAlgorithm::kEsch;
  std::string why;
  EXPECT_FALSE(options.is_valid(&why));
  EXPECT_NE(why.find("max_evaluations"), std::string::npos);
  options.max_evaluations = 100;
  EXPECT_TRUE(options.is_valid(&why));
}

}  // namespace
}  // namespace motoflex_es
