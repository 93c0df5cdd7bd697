#include "fit_sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motoflex::detail {

std::vector<double> fitness_sensitivity(FitProblem& problem, motoflex_es::Evaluator& evaluator,
                                        const std::vector<double>& best_x) {
  const motoflex_es::Bounds bounds = problem.bounds();
  const std::size_t n = best_x.size();
  std::vector<std::vector<double>> xs{best_x};
  std::vector<double> step(n, 0.0);  // the share of the width actually moved (one side)
  for (std::size_t i = 0; i < n; ++i) {
    const double width = bounds.upper[i] - bounds.lower[i];
    for (const double side : {1.0, -1.0}) {
      std::vector<double> x = best_x;
      x[i] =
          std::clamp(best_x[i] + side * kSensitivityStep * width, bounds.lower[i], bounds.upper[i]);
      step[i] = std::max(step[i], std::abs(x[i] - best_x[i]) / width);
      xs.push_back(std::move(x));
    }
  }
  const std::vector<std::uint64_t> counters = problem.counters();
  motoflex_es::EvaluationContext context;
  context.stop_threshold = std::numeric_limits<double>::infinity();
  std::vector<double> fitness;
  evaluator.evaluate(problem, xs, fitness, context);
  problem.set_counters(counters[0], counters[1], counters[2]);

  const double f0 = fitness[0];
  // A perfect fit (F* = 0) makes every change infinitely large relative to it; the smallest
  // positive double keeps the ratio finite and the parameter "determined".
  const double scale = std::max(std::abs(f0), std::numeric_limits<double>::min());
  std::vector<double> out(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(step[i] > 0.0)) continue;  // a zero-width range: nothing to move
    const double change =
        0.5 * (std::abs(fitness[1 + 2 * i] - f0) + std::abs(fitness[2 + 2 * i] - f0));
    out[i] = std::isfinite(change) ? change / (step[i] * scale)
                                   : std::numeric_limits<double>::infinity();
  }
  return out;
}

}  // namespace motoflex::detail
