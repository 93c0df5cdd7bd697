#pragma once

#include <string>
#include <vector>

#include "motoflex_es/problem.hpp"

namespace motoflex_es {

// Evaluates a batch of points through a Problem; the seam between a strategy and where the
// work runs (this process serially, OpenMP threads, MPI ranks). Every evaluator stores
// fitness[k] for xs[k] by index, never in completion order, and hands the problem the
// individual's index in the context, so a deterministic problem gives bit-identical results
// under every evaluator and any number of workers.
class Evaluator {
 public:
  virtual ~Evaluator() = default;

  // Resizes `fitness` to xs.size() and fills it. Exceptions from the problem propagate (when
  // several individuals throw, the one with the lowest index wins).
  virtual void evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                        std::vector<double>& fitness, const EvaluationContext& context) = 0;
  // For summaries and logs, e.g. "serial" or "openmp(4 threads)".
  virtual std::string name() const = 0;
  // How many individuals can be evaluated at once.
  virtual int workers() const = 0;
};

// The whole batch in one Problem::evaluate_batch call in the calling thread.
class SerialEvaluator final : public Evaluator {
 public:
  void evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                std::vector<double>& fitness, const EvaluationContext& context) override;
  std::string name() const override { return "serial"; }
  int workers() const override { return 1; }
};

// One individual per Problem::evaluate_batch call, spread over `threads` OpenMP threads with
// dynamic scheduling (rollouts that stop early free their thread at once). The problem must
// allow concurrent calls (see Problem::evaluate_batch). threads <= 0 means OpenMP's default
// (omp_get_max_threads()). A batch of one individual is evaluated in the calling thread with
// every thread handed to the problem (EvaluationContext::spare_threads).
class OpenMpEvaluator final : public Evaluator {
 public:
  explicit OpenMpEvaluator(int threads);

  void evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                std::vector<double>& fitness, const EvaluationContext& context) override;
  std::string name() const override;
  int workers() const override { return threads_; }

 private:
  int threads_;
};

// MpiEvaluator (mpi_evaluator.hpp) spreads a batch over MPI ranks the same way: fixed
// contiguous slices, each rank with its own replica of the Problem, fitness gathered by index.

}  // namespace motoflex_es
