// A candidate the model rejects (negative backlash-like values, R = 0) is scored +inf, counted
// and named, and never ends the evaluation; bounds leaving a parameter's domain are rejected
// when the fit config is loaded, naming the parameter.

#include <gtest/gtest.h>

#include <cmath>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

TEST(InvalidCandidate, ScoredWorstCountedNeverThrown) {
  const fs::path dir = fresh_dir("invalid_candidate");
  record_pendulum_log(dir / "data", "sin_sin");
  const FitConfig config =
      load_fit_config(write_pendulum_fit(dir, dir / "data", "{kind: cma_es}", "{evaluations: 10}",
                                         "out: " + (dir / "run").string() + "\n"));
  // The space as the fit built it, then a copy whose R can reach 0 (what a config could ask for
  // before domains were checked): bench.R_ohm is fixed at 2.6 in the base.
  std::vector<FreeParameter> free = config.space->free_parameters();
  FreeParameter r;
  r.name = "bench.R_ohm";
  r.targets = {"bench.R_ohm"};
  r.lower = -1.0;
  r.upper = 5.0;
  r.start = 2.6;
  free.push_back(r);
  FitConfig bad = config;
  bad.space = std::make_shared<ParameterSpace>(free, config.space->base());
  FitProblem problem(bad);
  std::vector<double> good = bad.space->start();
  std::vector<double> zero = good, negative = good;
  zero.back() = 0.0;
  negative.back() = -0.5;
  std::vector<double> fitness(3);
  problem.evaluate_batch({good, zero, negative}, fitness, {});
  EXPECT_TRUE(std::isfinite(fitness[0]));
  EXPECT_GT(fitness[0], 0.0);
  EXPECT_TRUE(std::isinf(fitness[1]));
  EXPECT_TRUE(std::isinf(fitness[2]));
  EXPECT_EQ(problem.invalid_candidates(), 2u);
  ASSERT_EQ(problem.invalid_reasons().size(), 1u);
  EXPECT_NE(problem.invalid_reasons()[0].find("R_ohm"), std::string::npos);
  EXPECT_EQ(problem.counters().size(), 4u);
}

TEST(InvalidCandidate, BoundsOutsideTheDomainNameTheParameter) {
  const fs::path dir = fresh_dir("invalid_bounds");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string path = write_pendulum_fit(dir, dir / "data", "{kind: cma_es}",
                                              "{evaluations: 10}", "fixed: {bench.R_ohm: 2.6}\n");
  // Replace the friction bounds with ones reaching below 0.
  std::string text = read_text(path);
  const std::string from = "joint.pendulum.friction_nm: {lower: 0.001, upper: 0.5, log: true}";
  text.replace(text.find(from), from.size(),
               "joint.pendulum.friction_nm: {lower: -0.1, upper: 0.5}");
  write_text(path, text);
  try {
    load_fit_config(path);
    FAIL() << "bounds below 0 accepted for a friction";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "free.joint.pendulum.friction_nm");
    EXPECT_NE(error.message().find("domain of joint.pendulum.friction_nm (a number >= 0)"),
              std::string::npos)
        << error.message();
  }
  const std::string fixed = "fixed: {bench.R_ohm: 2.6}";
  text.replace(text.find(fixed), fixed.size(), "fixed: {bench.R_ohm: 0}");
  text.replace(text.find("{lower: -0.1, upper: 0.5}"), 25, "{lower: 0.0, upper: 0.5}");
  write_text(path, text);
  try {
    load_fit_config(path);
    FAIL() << "R = 0 accepted as a fixed value";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("bench.R_ohm = 0 is outside its domain"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace motoflex::testing
