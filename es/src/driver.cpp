#include "motoflex_es/driver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace motoflex_es {
namespace {

void check_dimensions(const char* caller, const Strategy& strategy, const Problem& problem) {
  if (problem.dimension() != strategy.dimension()) {
    throw std::invalid_argument(std::string(caller) + ": the problem has dimension " +
                                std::to_string(problem.dimension()) + ", the strategy " +
                                std::to_string(strategy.dimension()));
  }
}

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string format_double(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

// Whether the run ends before the next generation (the strategy is done, or the generation or
// evaluation budget would be exceeded); if so, says why in `summary`.
bool stops_before_generation(const Strategy& strategy, const Budget& budget, RunSummary& summary) {
  if (strategy.should_stop()) {
    summary.reason = RunStopReason::kStrategy;
    summary.reason_detail = std::string("strategy: ") + to_string(strategy.stop_reason());
    if (!strategy.stop_detail().empty())
      summary.reason_detail += " (" + strategy.stop_detail() + ")";
    return true;
  }
  if (budget.max_generations > 0 && strategy.generation() >= budget.max_generations) {
    summary.reason = RunStopReason::kMaxGenerations;
    summary.reason_detail = "max_generations = " + std::to_string(budget.max_generations);
    return true;
  }
  if (budget.max_evaluations > 0 &&
      strategy.evaluations() + strategy.next_batch_size() > budget.max_evaluations) {
    summary.reason = RunStopReason::kMaxEvaluations;
    summary.reason_detail = "max_evaluations = " + std::to_string(budget.max_evaluations);
    return true;
  }
  return false;
}

// The generation's counts and batch statistics after `tell` (`sorted` is scratch space).
GenerationReport generation_report(const Strategy& strategy, const std::vector<double>& fitness,
                                   double best_before, std::vector<double>& sorted) {
  GenerationReport report;
  report.generation = strategy.generation();
  report.evaluations = strategy.evaluations();
  report.batch_size = fitness.size();
  sorted.clear();
  for (double f : fitness) sorted.push_back(ranked_fitness(f));
  std::sort(sorted.begin(), sorted.end());
  report.batch_best = sorted.front();
  report.batch_median = sorted[sorted.size() / 2];
  report.best_fitness = strategy.best_fitness();
  report.improved = strategy.best_fitness() < best_before;
  return report;
}

// Racing: the first exact_ranks_needed() individuals are evaluated against the strategy's
// selection threshold; the rest follow in chunks of Strategy::race_chunk, each against
// Strategy::race_threshold of the values known exactly so far. An individual stopped there
// cannot influence the run, and every individual that can is evaluated in full, so the
// strategy's ranks that matter and their values are those of a full evaluation. Chunks keep
// the batch's indices (EvaluationContext::first_individual), so a problem's random streams are
// those of a full evaluation too.
void evaluate_racing(Evaluator& evaluator, Problem& problem, const Strategy& strategy,
                     const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                     const EvaluationContext& context) {
  const std::size_t exact = strategy.exact_ranks_needed();
  if (exact == 0 || exact >= xs.size()) {
    evaluator.evaluate(problem, xs, fitness, context);
    return;
  }
  fitness.clear();
  std::vector<double> exact_values;  // ranked values of the individuals not stopped, ascending
  std::vector<double> chunk_fitness;
  const std::size_t chunk_size = std::max<std::size_t>(
      1, strategy.race_chunk(static_cast<std::size_t>(std::max(1, evaluator.workers()))));
  std::size_t begin = 0;
  while (begin < xs.size()) {
    const std::size_t end = std::min(xs.size(), begin + (begin == 0 ? exact : chunk_size));
    EvaluationContext chunk = context;
    chunk.first_individual = context.first_individual + begin;
    if (begin > 0) {
      chunk.stop_threshold =
          std::min(context.stop_threshold, strategy.race_threshold(exact_values));
    }
    evaluator.evaluate(
        problem,
        std::vector<std::vector<double>>(xs.begin() + static_cast<std::ptrdiff_t>(begin),
                                         xs.begin() + static_cast<std::ptrdiff_t>(end)),
        chunk_fitness, chunk);
    for (const double f : chunk_fitness) {
      fitness.push_back(f);
      // A value at or above the threshold may be a stopped individual's partial sum.
      if (ranked_fitness(f) < chunk.stop_threshold) {
        exact_values.insert(
            std::upper_bound(exact_values.begin(), exact_values.end(), ranked_fitness(f)),
            ranked_fitness(f));
      }
    }
    begin = end;
  }
}

}  // namespace

const char* to_string(RunStopReason reason) {
  switch (reason) {
    case RunStopReason::kStrategy:
      return "strategy";
    case RunStopReason::kMaxGenerations:
      return "max_generations";
    case RunStopReason::kMaxEvaluations:
      return "max_evaluations";
    case RunStopReason::kMaxSeconds:
      return "max_seconds";
    case RunStopReason::kCallback:
      return "callback";
  }
  return "unknown";
}

std::string RunSummary::brief_report() const {
  std::ostringstream out;
  out << strategy << ": " << reason_detail << " after " << generations << " generations, "
      << evaluations << " evaluations, best " << format_double(best_fitness) << " ("
      << format_double(seconds) << " s)";
  return out.str();
}

std::string RunSummary::full_report() const {
  std::ostringstream out;
  out << "strategy            " << strategy << "\n"
      << "evaluator           " << evaluator << "\n"
      << "stopped             " << reason_detail << "\n"
      << "generations         " << generations << " (" << generations_this_call
      << " in this call)\n"
      << "evaluations         " << evaluations << " (" << evaluations_this_call
      << " in this call)\n"
      << "best fitness        " << format_double(best_fitness) << "\n"
      << "time                " << format_double(seconds) << " s, of which evaluation "
      << format_double(evaluation_seconds) << " s\n"
      << "best x              [";
  for (std::size_t i = 0; i < best_x.size(); ++i) {
    out << (i == 0 ? "" : ", ") << format_double(best_x[i]);
  }
  out << "]\n";
  return out.str();
}

RunSummary run_optimisation(Strategy& strategy, Problem& problem, Evaluator& evaluator,
                            const Budget& budget, const RunCallbacks& callbacks) {
  check_dimensions("run_optimisation", strategy, problem);
  const Clock::time_point start = Clock::now();
  const std::uint64_t generations_before = strategy.generation();
  const std::uint64_t evaluations_before = strategy.evaluations();
  RunSummary summary;
  summary.strategy = strategy.name();
  summary.evaluator = evaluator.name();
  std::vector<double> fitness;
  std::vector<double> sorted;

  while (true) {
    if (stops_before_generation(strategy, budget, summary)) break;

    EvaluationContext context;
    context.generation = strategy.generation();
    context.first_individual = 0;
    context.stop_threshold = strategy.selection_threshold();
    const std::vector<std::vector<double>> xs = strategy.ask();
    if (xs.empty()) {
      // Only a strategy that just found out it is done may return nothing; the check at the top
      // of the loop then reports why.
      if (!strategy.should_stop()) {
        throw std::logic_error(strategy.name() + " returned an empty batch without stopping");
      }
      continue;
    }

    const Clock::time_point evaluation_start = Clock::now();
    evaluate_racing(evaluator, problem, strategy, xs, fitness, context);
    const double evaluation_seconds = seconds_since(evaluation_start);
    summary.evaluation_seconds += evaluation_seconds;

    const double best_before = strategy.best_fitness();
    strategy.tell(fitness);

    GenerationReport report = generation_report(strategy, fitness, best_before, sorted);
    report.stop_threshold = context.stop_threshold;
    report.evaluation_seconds = evaluation_seconds;
    report.elapsed_seconds = seconds_since(start);
    if (callbacks.on_generation && !callbacks.on_generation(strategy, report)) {
      summary.reason = RunStopReason::kCallback;
      summary.reason_detail = "stopped by the per-generation callback";
      break;
    }
    if (budget.max_seconds > 0.0 && report.elapsed_seconds >= budget.max_seconds) {
      summary.reason = RunStopReason::kMaxSeconds;
      summary.reason_detail = "max_seconds = " + format_double(budget.max_seconds);
      break;
    }
  }

  summary.generations = strategy.generation();
  summary.evaluations = strategy.evaluations();
  summary.generations_this_call = summary.generations - generations_before;
  summary.evaluations_this_call = summary.evaluations - evaluations_before;
  summary.best_fitness = strategy.best_fitness();
  summary.best_x = strategy.best_x();
  summary.seconds = seconds_since(start);
  return summary;
}

double evaluate_incumbent(Strategy& strategy, Problem& problem, Evaluator& evaluator,
                          const std::vector<double>& x) {
  check_dimensions("evaluate_incumbent", strategy, problem);
  EvaluationContext context;
  context.generation = strategy.generation();
  std::vector<double> fitness;
  evaluator.evaluate(problem, {x}, fitness, context);
  strategy.record_incumbent(x, fitness.front());
  return fitness.front();
}

}  // namespace motoflex_es
