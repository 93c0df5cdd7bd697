#include "motoflex_es/driver.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace motoflex_es {
namespace {

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
  if (problem.dimension() != strategy.dimension()) {
    throw std::invalid_argument("run_optimisation: the problem has dimension " +
                                std::to_string(problem.dimension()) + ", the strategy " +
                                std::to_string(strategy.dimension()));
  }
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
    evaluator.evaluate(problem, xs, fitness, context);
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

}  // namespace motoflex_es
