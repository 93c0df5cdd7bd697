// NLopt's algorithms as fit strategies: the global ones run to the fit's evaluation budget,
// which is therefore required; a serial algorithm's point is evaluated on several threads
// without changing the run.

#include <gtest/gtest.h>

#include <algorithm>
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

TEST(FitNlopt, GlobalAlgorithmsRunToTheEvaluationBudget) {
  for (const std::string algorithm : {"crs2_lm", "isres"}) {
    const fs::path dir = fresh_dir("fit_nlopt_" + algorithm);
    const std::string fit =
        write_pendulum_fit(dir, kHiddenNone, "{kind: nlopt, algorithm: " + algorithm + "}",
                           "{evaluations: 30}", "out: " + (dir / "run").string() + "\n");
    FitSession(load_fit_config(fit), false).run();
    const auto summary = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
    EXPECT_EQ(summary["evaluations"].get<int>(), 30) << algorithm;
    // One point per generation: 30 rows under the header.
    const std::string csv = read_text(dir / "run" / "generations.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 31) << algorithm;
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
