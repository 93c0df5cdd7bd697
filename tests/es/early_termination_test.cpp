// Early termination: a problem may stop a rollout once its partial error reaches the strategy's
// selection threshold. These tests check that this changes nothing but the work done.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/driver.hpp"
#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "test_problems.hpp"

namespace motoflex_es {
namespace {

// Fitness = Σ_t e_t(x) over kSteps "time steps", every e_t >= 0, like the angle error of a
// rollout summed over its frames. With `quantised` every e_t is an integer, so many
// individuals tie, exactly at the threshold too.
class PartialErrorProblem : public Problem {
 public:
  static constexpr int kSteps = 60;

  PartialErrorProblem(bool stop_early, bool quantised)
      : stop_early_(stop_early), quantised_(quantised) {}

  std::size_t dimension() const override { return 5; }
  Bounds bounds() const override {
    return Bounds{std::vector<double>(5, -3.0), std::vector<double>(5, 3.0)};
  }
  void evaluate_batch(const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                      const EvaluationContext& context) override {
    for (std::size_t k = 0; k < xs.size(); ++k) {
      double sum = 0.0;
      for (int t = 0; t < kSteps; ++t) {
        ++steps_;
        const std::size_t i = static_cast<std::size_t>(t) % 5;
        const double target = std::sin(0.3 * t) + 0.1 * static_cast<double>(i);
        const double d = xs[k][i] - target;
        const double error = (1.0 + 0.5 * std::cos(0.7 * t)) * d * d;
        sum += quantised_ ? std::floor(4.0 * error) : error;
        // The partial sum can only grow: once it reaches the threshold the individual is lost.
        if (stop_early_ && sum >= context.stop_threshold && t + 1 < kSteps) {
          ++stopped_;
          break;
        }
      }
      fitness[k] = sum;
    }
  }
  std::uint64_t steps() const { return steps_.load(); }
  std::uint64_t stopped() const { return stopped_.load(); }

 private:
  bool stop_early_;
  bool quantised_;
  std::atomic<std::uint64_t> steps_{0};
  std::atomic<std::uint64_t> stopped_{0};
};

struct Trace {
  std::vector<std::string> states;  // save_state() after every generation
  std::uint64_t steps = 0;
  std::uint64_t stopped = 0;
  std::uint64_t evaluations = 0;
};

Trace run(Strategy& strategy, bool stop_early, bool quantised, Evaluator& evaluator,
          std::uint64_t generations = 40) {
  PartialErrorProblem problem(stop_early, quantised);
  Trace trace;
  Budget budget;
  budget.max_generations = generations;
  RunCallbacks callbacks;
  callbacks.on_generation = [&trace](const Strategy& s, const GenerationReport&) {
    trace.states.push_back(s.save_state().dump());
    return true;
  };
  run_optimisation(strategy, problem, evaluator, budget, callbacks);
  trace.steps = problem.steps();
  trace.stopped = problem.stopped();
  trace.evaluations = strategy.evaluations();
  return trace;
}

MuPlusLambdaOptions small_es(std::uint64_t kappa, bool racing = true) {
  MuPlusLambdaOptions options;
  options.racing = racing;
  options.mu = 6;
  options.lambda = 80;
  options.kappa = kappa;
  options.seed = 21;
  return options;
}

TEST(EsEarlyTerminationTest, StoppingAtTheThresholdChangesNothingButTheWork) {
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  for (bool quantised : {false, true}) {
    for (std::uint64_t kappa : {std::uint64_t{1}, std::uint64_t{3}, kUnlimitedLifetime}) {
      SerialEvaluator serial;
      MuPlusLambda full_es(bounds, small_es(kappa));
      const Trace full = run(full_es, false, quantised, serial);
      // Against the parents alone (no racing within the generation): the baseline.
      OpenMpEvaluator two(2);
      MuPlusLambda parents_es(bounds, small_es(kappa, false));
      const Trace parents_only = run(parents_es, true, quantised, two);
      ASSERT_EQ(parents_only.states, full.states);
      // Racing chunks are μ individuals whatever the evaluator's width, so 1, 2 or 3 workers
      // stop the same individuals at the same values.
      std::vector<Trace> early_by_width;
      for (int workers : {1, 2, 3}) {
        OpenMpEvaluator threads(workers);
        MuPlusLambda early_es(bounds, small_es(kappa));
        const Trace early = run(early_es, true, quantised, threads);
        ASSERT_EQ(full.states.size(), early.states.size());
        for (std::size_t g = 0; g < full.states.size(); ++g) {
          // Population (x, step sizes, fitness, ages), best so far, counts: all identical.
          ASSERT_EQ(early.states[g], full.states[g])
              << "generation " << g << ", quantised " << quantised << ", kappa " << kappa
              << ", workers " << workers;
        }
        EXPECT_EQ(early_es.best_x(), full_es.best_x());
        if (!early_by_width.empty()) {
          EXPECT_EQ(early.steps, early_by_width.front().steps) << "workers " << workers;
          EXPECT_EQ(early.stopped, early_by_width.front().stopped) << "workers " << workers;
        }
        early_by_width.push_back(early);
      }
      const Trace& early = early_by_width.front();
      const auto saved = [&full](const Trace& t) {
        return 100.0 * (1.0 - static_cast<double>(t.steps) / static_cast<double>(full.steps));
      };
      std::printf(
          "(6+80)-ES, kappa %llu, quantised %d: %llu of %llu stopped, %.1f %% of the "
          "steps saved (against the parents alone: %.1f %%)\n",
          static_cast<unsigned long long>(kappa), static_cast<int>(quantised),
          static_cast<unsigned long long>(early.stopped),
          static_cast<unsigned long long>(early.evaluations), saved(early), saved(parents_only));
      // Measured (seed 21, 40 generations, 3126 evaluations): racing within the generation
      // saves 5-13 % of the steps; against the parents alone 0-11 %, nothing for κ = 1, which
      // keeps no parents to compare with. An offspring near its parents only proves itself
      // worse late in this sum.
      EXPECT_LT(early.steps, parents_only.steps)
          << "quantised " << quantised << ", kappa " << kappa;
      EXPECT_EQ(full.stopped, 0u);
    }
  }
}

TEST(EsEarlyTerminationTest, CommaSelectionRacesWithinTheBatchAndCmaEsOffersNoThreshold) {
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  SerialEvaluator serial;
  // Comma selection keeps no parent, so there is no threshold before the batch ...
  MuPlusLambda comma(bounds, small_es(1));
  run(comma, false, false, serial, 1);
  EXPECT_EQ(comma.selection_threshold(), std::numeric_limits<double>::infinity());
  // ... but the μ-th best offspring so far bounds the rest of the batch.
  EXPECT_EQ(comma.exact_ranks_needed(), 6u);
  EXPECT_EQ(comma.race_threshold({1.0, 2.0, 3.0, 4.0, 5.0}),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(comma.race_threshold({1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0}), 6.0);

  CmaEs cma_full(bounds, CmaEsOptions{}), cma_early(bounds, CmaEsOptions{});
  const Trace full = run(cma_full, false, false, serial);
  const Trace early = run(cma_early, true, false, serial);
  EXPECT_EQ(early.states, full.states);
  EXPECT_EQ(early.steps, full.steps);  // the active update reads every rank: nothing is stopped
}

TEST(EsEarlyTerminationTest, TheRaceChunkChangesOnlyTheWork) {
  // One offspring per chunk (the tightest bound), the default μ = 6, and one chunk for the whole
  // rest of the generation: the same states, and the default saves more than the one big chunk.
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  SerialEvaluator serial;
  MuPlusLambda full_es(bounds, small_es(3));
  const Trace full = run(full_es, false, false, serial);
  std::vector<std::uint64_t> steps;
  for (std::size_t chunk : {std::size_t{1}, std::size_t{0}, std::size_t{80}}) {
    MuPlusLambdaOptions options = small_es(3);
    options.race_chunk = chunk;
    MuPlusLambda es(bounds, options);
    OpenMpEvaluator two(2);
    const Trace raced = run(es, true, false, two);
    EXPECT_EQ(raced.states, full.states) << "race_chunk " << chunk;
    EXPECT_EQ(es.race_chunk(2), chunk == 0 ? 6u : chunk);
    steps.push_back(raced.steps);
  }
  EXPECT_LT(steps[1], steps[2]);
  EXPECT_LE(steps[0], steps[1]);
}

TEST(EsEarlyTerminationTest, PlusSelectionRacesAgainstParentsAndEarlierOffspringTogether) {
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  SerialEvaluator serial;
  MuPlusLambda es(bounds, small_es(kUnlimitedLifetime));
  run(es, false, false, serial, 2);
  std::vector<double> parents;
  for (const Individual& parent : es.population()) parents.push_back(parent.fitness);
  ASSERT_EQ(parents.size(), 6u);
  std::sort(parents.begin(), parents.end());
  EXPECT_EQ(es.selection_threshold(), parents[5]);
  EXPECT_EQ(es.race_threshold({}), parents[5]);
  // Two offspring better than every parent push the bound down to the parents' 4th best;
  // offspring worse than the parents leave it where it is.
  const double below = parents[0] / 2.0;
  EXPECT_EQ(es.race_threshold({below, below}), parents[3]);
  EXPECT_EQ(es.race_threshold({parents[5] * 2.0}), parents[5]);
}

CmaEsOptions plain_cma(bool racing, double tol_fun) {
  CmaEsOptions options;
  options.active = false;  // racing needs the original rank-μ update
  options.racing = racing;
  options.tol_fun = tol_fun;
  options.max_restarts = 2;
  options.seed = 5;
  return options;
}

// Runs `options(racing, tol_fun)` with and without racing and expects the same states, best and
// stop reason, with work saved. tol_fun 1e-12 never fires in 150 generations; 1e-3 ends runs
// (and restarts with a larger λ) inside them, so the generations where racing must give way to
// a full evaluation occur.
void expect_racing_changes_nothing_but_the_work(CmaEsOptions (*options)(bool, double),
                                                const char* what) {
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  for (double tol_fun : {1e-12, 1e-3}) {
    for (bool quantised : {false, true}) {
      SerialEvaluator serial;
      OpenMpEvaluator threads(2);
      CmaEs full_cma(bounds, options(false, tol_fun));
      CmaEs racing_cma(bounds, options(true, tol_fun));
      const Trace full = run(full_cma, false, quantised, serial, 150);
      const Trace raced = run(racing_cma, true, quantised, threads, 150);
      ASSERT_EQ(full.states.size(), raced.states.size());
      for (std::size_t g = 0; g < full.states.size(); ++g) {
        // Mean, σ, paths, covariance, histories, best so far, restarts: all identical.
        ASSERT_EQ(raced.states[g], full.states[g]) << what << ", generation " << g << ", quantised "
                                                   << quantised << ", tol_fun " << tol_fun;
      }
      EXPECT_EQ(racing_cma.best_x(), full_cma.best_x());
      EXPECT_EQ(racing_cma.stop_reason(), full_cma.stop_reason());
      std::printf(
          "%s racing, tol_fun %g, quantised %d: %llu of %llu evaluations stopped, "
          "%.1f %% of the steps saved, %zu restarts\n",
          what, tol_fun, static_cast<int>(quantised),
          static_cast<unsigned long long>(raced.stopped),
          static_cast<unsigned long long>(raced.evaluations),
          100.0 * (1.0 - static_cast<double>(raced.steps) / full.steps), racing_cma.restarts());
      // Measured (seed 5, 150 generations, one restart, rank-mu update): 65-83 of ~1500
      // evaluations stopped, 0.7-0.8 % of the steps saved. Racing cannot save much here: only
      // the samples after the first max(μ, λ/2+1) can be stopped, and they only prove themselves
      // worse late in the sum.
      EXPECT_GT(raced.stopped, raced.evaluations / 50);
      EXPECT_LT(raced.steps, full.steps);
    }
  }
}

TEST(EsEarlyTerminationTest, CmaEsRacingChangesNothingButTheWork) {
  expect_racing_changes_nothing_but_the_work(plain_cma, "CMA-ES (rank-mu)");
}

CmaEsOptions pooled_active_cma(bool racing, double tol_fun) {
  CmaEsOptions options = plain_cma(racing, tol_fun);
  options.active = true;
  options.pooled_negative_tail = true;
  return options;
}

// The raced tail's partial sums sort differently from its full values; the pooled update reads
// only which samples are in the tail, so every state is the same.
TEST(EsEarlyTerminationTest, PooledActiveCmaEsRacingChangesNothingButTheWork) {
  expect_racing_changes_nothing_but_the_work(pooled_active_cma, "active CMA-ES (pooled tail)");
}

TEST(EsEarlyTerminationTest, PooledTailIsStillAnActiveUpdate) {
  // The pooled variant is neither the ranked active update nor the plain rank-μ one: its
  // covariance differs from both after one generation, and it converges on the sphere-like
  // problem as well (best within 10 % of the ranked update's after 150 generations).
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  SerialEvaluator serial;
  CmaEsOptions ranked_options = pooled_active_cma(false, 1e-12);
  ranked_options.pooled_negative_tail = false;
  CmaEs pooled(bounds, pooled_active_cma(false, 1e-12)), ranked(bounds, ranked_options),
      plain(bounds, plain_cma(false, 1e-12));
  const Trace a = run(pooled, false, false, serial, 150),
              b = run(ranked, false, false, serial, 150), c = run(plain, false, false, serial, 150);
  EXPECT_NE(a.states.front(), b.states.front());
  EXPECT_NE(a.states.front(), c.states.front());
  EXPECT_LT(pooled.best_fitness(), 1.1 * ranked.best_fitness() + 1e-9);
  CmaEs fresh(bounds, pooled_active_cma(true, 1e-12));
  const std::size_t lambda = fresh.next_batch_size();
  EXPECT_EQ(fresh.exact_ranks_needed(), std::max(fresh.parameters().mu, lambda / 2 + 1));
  EXPECT_LT(fresh.exact_ranks_needed(), lambda);
}

TEST(EsEarlyTerminationTest, ActiveCmaEsNeedsEveryRank) {
  const Bounds bounds = PartialErrorProblem(false, false).bounds();
  CmaEs active(bounds, CmaEsOptions{});
  EXPECT_EQ(active.exact_ranks_needed(), active.next_batch_size());
  CmaEs plain(bounds, plain_cma(true, 1e-12));
  const std::size_t lambda = plain.next_batch_size();
  EXPECT_EQ(plain.exact_ranks_needed(), std::max(plain.parameters().mu, lambda / 2 + 1));
  CmaEs off(bounds, plain_cma(false, 1e-12));
  EXPECT_EQ(off.exact_ranks_needed(), lambda);
}

}  // namespace
}  // namespace motoflex_es
