#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/problem.hpp"
#include "motoflex_es/strategy.hpp"

namespace motoflex_es {

// Limits of one run_optimisation call; 0 means no limit. Generations and evaluations count the
// strategy's totals (Strategy::generation(), ::evaluations()), including those before a resume,
// so a resumed run stops exactly where an uninterrupted one would.
struct Budget {
  // Stop once strategy.generation() >= max_generations.
  std::uint64_t max_generations = 0;
  // Never start a batch that would take strategy.evaluations() above max_evaluations.
  std::uint64_t max_evaluations = 0;
  // Wall-clock seconds of this call, checked after every generation (so a run may overrun by
  // up to one generation). Not reproducible by nature.
  double max_seconds = 0.0;
};

// What happened in one generation, handed to the per-generation callback.
struct GenerationReport {
  std::uint64_t generation = 0;   // strategy.generation() after the tell
  std::uint64_t evaluations = 0;  // strategy.evaluations() after the tell
  std::size_t batch_size = 0;
  double batch_best = std::numeric_limits<double>::infinity();    // NaN counted as +inf
  double batch_median = std::numeric_limits<double>::infinity();  // of reported values
  double best_fitness = std::numeric_limits<double>::infinity();  // best so far
  bool improved = false;  // the best so far improved in this generation
  // The early-termination threshold handed to the problem (+inf: none). Individuals stopped
  // early report values >= it, so batch_median is then a censored statistic.
  double stop_threshold = std::numeric_limits<double>::infinity();
  double evaluation_seconds = 0.0;  // wall clock spent in the evaluator for this batch
  double elapsed_seconds = 0.0;     // since run_optimisation started
};

struct RunCallbacks {
  // Called after every tell, when the strategy's state is complete and consistent (the place
  // to write a checkpoint, a progress line or a CSV row). Return false to stop the run.
  std::function<bool(const Strategy&, const GenerationReport&)> on_generation;
};

enum class RunStopReason {
  kStrategy,        // the strategy stopped itself (see Strategy::stop_reason())
  kMaxGenerations,  // Budget::max_generations
  kMaxEvaluations,  // Budget::max_evaluations: the next batch would not fit
  kMaxSeconds,      // Budget::max_seconds
  kCallback,        // on_generation returned false
};
const char* to_string(RunStopReason reason);

// Ceres-style summary of one run_optimisation call.
struct RunSummary {
  std::string strategy;
  std::string evaluator;
  RunStopReason reason = RunStopReason::kStrategy;
  std::string reason_detail;      // one line, e.g. "strategy: tol_fun (run 0 (lambda 10): ...)"
  std::uint64_t generations = 0;  // strategy total at the end
  std::uint64_t evaluations = 0;  // strategy total at the end
  std::uint64_t generations_this_call = 0;
  std::uint64_t evaluations_this_call = 0;
  double best_fitness = std::numeric_limits<double>::infinity();
  std::vector<double> best_x;
  double seconds = 0.0;             // wall clock of the call
  double evaluation_seconds = 0.0;  // of which in the evaluator

  // One line: "cma_es: tol_fun after 120 generations, 1200 evaluations, best 1.2e-09 (0.3 s)".
  std::string brief_report() const;
  // Several lines: every field above, with the best point.
  std::string full_report() const;
};

// Runs ask → evaluate → tell until the strategy stops or the budget or the callback ends it.
// Each batch is evaluated with context {generation = strategy.generation(), first_individual = 0,
// stop_threshold = strategy.selection_threshold()}. The strategy may have been resumed from a
// checkpoint. Throws std::invalid_argument if the problem's dimension differs from the
// strategy's; exceptions of the problem or the callback propagate (the strategy is then left
// with an outstanding ask, which a later ask() simply repeats).
RunSummary run_optimisation(Strategy& strategy, Problem& problem, Evaluator& evaluator,
                            const Budget& budget, const RunCallbacks& callbacks = {});

// Evaluates x in full (never stopped early; context {generation = strategy.generation(),
// first_individual = 0}) and hands it to Strategy::record_incumbent, so the run's best is never
// worse than x. Returns its fitness. Call it before run_optimisation on a fresh strategy.
double evaluate_incumbent(Strategy& strategy, Problem& problem, Evaluator& evaluator,
                          const std::vector<double>& x);

}  // namespace motoflex_es
