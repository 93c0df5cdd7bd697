// fitness.error: absolute — the error sum is Σ_t Σ_i w_i·|q_real − q_sim| (BAM's loss), computed
// here by hand from the rollout; the least-squares residual of a channel squares to that term;
// the loop's error summary and BIC follow it; squared stays seed 001's sum and the default (same
// run hash as before the option); a bad value names the field.

#include <gtest/gtest.h>

#include <cmath>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_run.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// Σ over the scored frames of |e| (absolute) or e² of the one pendulum joint.
double error_sum_by_hand(const FitnessFunction& fitness, const RolloutResult& rollout,
                         bool absolute) {
  const FitCase& fit_case = fitness.cases()[0];
  double sum = 0.0;
  for (std::size_t f = 0; f < fit_case.commands.frames(); ++f) {
    const double e = fit_case.measured_rad[f] - rollout.measured_rad[f];
    sum += absolute ? std::abs(e) : e * e;
  }
  return sum;
}

TEST(FitnessAbsoluteError, SumsAbsoluteDifferences) {
  const fs::path dir = fresh_dir("fitness_absolute");
  record_pendulum_log(dir / "data", "sin_sin");
  const FitConfig squared = pendulum_fitness_config(dir / "squared", dir / "data", "{m: 2}");
  const FitConfig absolute =
      pendulum_fitness_config(dir / "absolute", dir / "data", "{m: 2, error: absolute}");
  // An off-truth point, so that every frame adds error.
  const ParameterSet point = absolute.space->apply(absolute.space->start());
  std::vector<RolloutResult> rollouts_a, rollouts_s;
  const FitnessBreakdown a = absolute.train->evaluate(point, INFINITY, &rollouts_a);
  const FitnessBreakdown s = squared.train->evaluate(point, INFINITY, &rollouts_s);
  ASSERT_EQ(a.cases[0].frames, a.cases[0].frames_requested);
  const double t_m = std::pow(static_cast<double>(a.cases[0].frames), 2.0);
  const double by_hand_abs = error_sum_by_hand(*absolute.train, rollouts_a[0], true);
  const double by_hand_sq = error_sum_by_hand(*squared.train, rollouts_s[0], false);
  EXPECT_NEAR(a.cases[0].squared_error_rad2, by_hand_abs, 1e-12 * by_hand_abs);
  EXPECT_NEAR(a.fitness, by_hand_abs / t_m, 1e-12 * a.fitness);
  EXPECT_NEAR(s.fitness, by_hand_sq / t_m, 1e-12 * s.fitness);
  // Errors of a few hundredths of a rad: |e| is far above e².
  EXPECT_GT(a.fitness, 5.0 * s.fitness);
  // A channel's residual squares to its term of the sum, with its sign.
  for (const double d : {0.25, -0.04, 0.0}) {
    const double r = absolute.train->channel_residual(0, d);
    EXPECT_NEAR(r * r, std::abs(d), 1e-15) << d;
    EXPECT_EQ(std::signbit(r), std::signbit(d)) << d;
    EXPECT_EQ(squared.train->channel_residual(0, d), d);
  }
  // The loop judges a refit by the fit's own error: the mean |e| here, the RMS for squared.
  const ErrorSummary abs_summary = summarize_errors(*absolute.train, point, 3);
  const ErrorSummary sq_summary = summarize_errors(*squared.train, point, 3);
  const double n = static_cast<double>(abs_summary.samples);
  EXPECT_NEAR(abs_summary.fit_error_rad, by_hand_abs / n, 1e-12 * abs_summary.fit_error_rad);
  EXPECT_NEAR(abs_summary.fit_error_rad, abs_summary.mae_rad, 1e-12 * abs_summary.mae_rad);
  EXPECT_EQ(sq_summary.fit_error_rad, sq_summary.channel_rms_rad);
  EXPECT_NEAR(abs_summary.bic, 2.0 * n * std::log(by_hand_abs / n) + 3.0 * std::log(n), 1e-9 * n);
  EXPECT_NE(absolute.hash, squared.hash);
  EXPECT_EQ(pendulum_fitness_config(dir / "explicit", dir / "data", "{m: 2, error: squared}").hash,
            squared.hash);
}

TEST(FitnessAbsoluteError, BadValueNamesTheField) {
  const fs::path dir = fresh_dir("fitness_absolute_bad");
  record_pendulum_log(dir / "data", "sin_sin");
  try {
    pendulum_fitness_config(dir, dir / "data", "{m: 2, error: l1}");
    FAIL() << "accepted error: l1";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "fitness.error");
    EXPECT_NE(std::string(error.what()).find("squared or absolute"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace motoflex::testing
