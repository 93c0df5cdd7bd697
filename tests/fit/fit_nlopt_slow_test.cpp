// NLopt's algorithms as fit strategies: the global ones run to the fit's evaluation budget,
// which is therefore required; a serial algorithm's point is evaluated on several threads
// without changing the run.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex/fit/fit_session.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const std::string kHiddenNone =
    std::string(MOTOFLEX_SOURCE_DIR) + "/reference_data/hidden/none/train";

TEST(FitNlopt, GlobalAlgorithmsSearchAndRunToTheEvaluationBudget) {
  for (const std::string algorithm : {"crs2_lm", "isres"}) {
    const fs::path dir = fresh_dir("fit_nlopt_" + algorithm);
    // Every parameter starts far from the truth of these logs, so that a search that finds
    // nothing better than its start fails the test.
    const std::string fit =
        write_pendulum_fit(dir, kHiddenNone, "{kind: nlopt, algorithm: " + algorithm + "}",
                           "{evaluations: 60}", "out: " + (dir / "run").string() + "\n");
    const FitConfig far = [&] {
      FitSpec spec = load_fit_spec(fit);
      for (FreeParameterSpec& p : spec.free) p.start = p.upper.value() * 0.9;
      return resolve_fit_config(spec);
    }();
    const double start_fitness = far.train->evaluate(far.space->apply(far.space->start())).fitness;
    const FitSummary result = FitSession(far, false).run();
    const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
    EXPECT_EQ(summary["evaluations"].get<int>(), 60) << algorithm;
    // One point per generation: 60 rows under the header.
    const std::string csv = read_text(dir / "run" / "generations.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 61) << algorithm;
    // It searched: the best point beats the start by an order of magnitude (measured: crs2_lm
    // 5.17e-4 → 1.28e-5, isres 5.17e-4 → 3.25e-5), and the run says it stopped at its budget
    // rather than converged.
    std::printf("%s: start %.6g -> best %.6g\n", algorithm.c_str(), start_fitness,
                result.best_fitness);
    EXPECT_LT(result.best_fitness, 0.1 * start_fitness) << algorithm;
    EXPECT_FALSE(result.converged) << algorithm;
    EXPECT_NE(result.stop_reason.find("evaluation"), std::string::npos) << result.stop_reason;
  }
}

// NLopt asks for one point at a time; with two threads the fit simulates that point's logs in
// parallel instead (the training folder has two), and the run is the same, bit for bit.
TEST(FitNlopt, OneAndTwoThreadsGiveIdenticalRuns) {
  const fs::path dir = fresh_dir("fit_nlopt_threads");
  const std::string fit =
      write_pendulum_fit(dir, kHiddenNone, "{kind: nlopt, algorithm: bobyqa}", "{evaluations: 40}");
  expect_one_and_two_threads_identical(fit, dir);
}

TEST(FitNlopt, AGlobalAlgorithmWithoutAnEvaluationBudgetIsBadInput) {
  const fs::path dir = fresh_dir("fit_nlopt_no_budget");
  const std::string fit =
      write_pendulum_fit(dir, kHiddenNone, "{kind: nlopt, algorithm: crs2_lm}", "{generations: 30}",
                         "out: " + (dir / "run").string() + "\n");
  try {
    make_strategy(load_fit_config(fit));
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "budget.evaluations");
  }
}

}  // namespace
}  // namespace motoflex::testing
