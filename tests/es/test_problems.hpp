#pragma once

// Benchmark functions and helpers shared by the es tests.

#include <atomic>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "motoflex_es/driver.hpp"
#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/problem.hpp"
#include "motoflex_es/strategy.hpp"

namespace motoflex_es::testing {

enum class Function { kSphere, kEllipsoid, kRosenbrock, kRastrigin };

inline const char* to_string(Function function) {
  switch (function) {
    case Function::kSphere:
      return "sphere";
    case Function::kEllipsoid:
      return "ellipsoid";
    case Function::kRosenbrock:
      return "rosenbrock";
    case Function::kRastrigin:
      return "rastrigin";
  }
  return "?";
}

// The optimum of sphere, ellipsoid and Rastrigin is moved off the centre of the box, to
// o_i = 1 − 0.2·i, so that neither the symmetric bounds nor the reflection can help; Rosenbrock
// keeps its optimum at (1, …, 1). Every optimum has fitness 0.
inline double optimum_coordinate(std::size_t i) {
  return 1.0 - 0.2 * static_cast<double>(i);
}

inline double benchmark(Function function, const std::vector<double>& x) {
  const std::size_t n = x.size();
  double sum = 0.0;
  switch (function) {
    case Function::kSphere:
      for (std::size_t i = 0; i < n; ++i) {
        const double d = x[i] - optimum_coordinate(i);
        sum += d * d;
      }
      return sum;
    case Function::kEllipsoid:  // condition number 1e6
      for (std::size_t i = 0; i < n; ++i) {
        const double d = x[i] - optimum_coordinate(i);
        const double exponent =
            n > 1 ? 6.0 * static_cast<double>(i) / static_cast<double>(n - 1) : 0;
        sum += std::pow(10.0, exponent) * d * d;
      }
      return sum;
    case Function::kRosenbrock:
      for (std::size_t i = 0; i + 1 < n; ++i) {
        const double a = x[i + 1] - x[i] * x[i];
        const double b = 1.0 - x[i];
        sum += 100.0 * a * a + b * b;
      }
      return sum;
    case Function::kRastrigin:
      for (std::size_t i = 0; i < n; ++i) {
        const double d = x[i] - optimum_coordinate(i);
        sum += d * d - 10.0 * std::cos(2.0 * std::numbers::pi * d) + 10.0;
      }
      return sum;
  }
  return sum;
}

// A benchmark function on the box [lower, upper]^n.
class BenchmarkProblem : public Problem {
 public:
  BenchmarkProblem(Function function, std::size_t n, double lower = -5.0, double upper = 5.0)
      : function_(function), n_(n), lower_(lower), upper_(upper) {}

  std::size_t dimension() const override { return n_; }
  Bounds bounds() const override {
    return Bounds{std::vector<double>(n_, lower_), std::vector<double>(n_, upper_)};
  }
  void evaluate_batch(const std::vector<std::vector<double>>& xs, std::vector<double>& fitness,
                      const EvaluationContext& /*context*/) override {
    for (std::size_t k = 0; k < xs.size(); ++k) fitness[k] = benchmark(function_, xs[k]);
    calls_ += xs.size();
  }
  std::uint64_t calls() const { return calls_.load(); }

 private:
  Function function_;
  std::size_t n_;
  double lower_;
  double upper_;
  std::atomic<std::uint64_t> calls_{0};
};

struct TargetResult {
  bool reached = false;
  std::uint64_t evaluations = 0;  // when the target was first reached (or at the end)
  double best = 0.0;
  RunSummary summary;
};

// Runs serially until the strategy stops or `max_evaluations` would be exceeded.
inline RunSummary run_serially(Strategy& strategy, Problem& problem,
                               std::uint64_t max_evaluations) {
  SerialEvaluator evaluator;
  Budget budget;
  budget.max_evaluations = max_evaluations;
  return run_optimisation(strategy, problem, evaluator, budget);
}

// Runs until best <= target or `max_evaluations` would be exceeded.
inline TargetResult run_to_target(Strategy& strategy, Problem& problem, double target,
                                  std::uint64_t max_evaluations) {
  SerialEvaluator evaluator;
  Budget budget;
  budget.max_evaluations = max_evaluations;
  RunCallbacks callbacks;
  callbacks.on_generation = [target](const Strategy&, const GenerationReport& report) {
    return report.best_fitness > target;
  };
  TargetResult result;
  result.summary = run_optimisation(strategy, problem, evaluator, budget, callbacks);
  result.best = strategy.best_fitness();
  result.reached = result.best <= target;
  result.evaluations = strategy.evaluations();
  return result;
}

}  // namespace motoflex_es::testing
