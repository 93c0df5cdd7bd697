#include "motoflex_es/evaluator.hpp"

#include <omp.h>

#include <exception>
#include <limits>
#include <string>

namespace motoflex_es {

void SerialEvaluator::evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                               std::vector<double>& fitness, const EvaluationContext& context) {
  fitness.assign(xs.size(), std::numeric_limits<double>::quiet_NaN());
  if (xs.empty()) return;
  problem.evaluate_batch(xs, fitness, context);
}

OpenMpEvaluator::OpenMpEvaluator(int threads)
    : threads_(threads > 0 ? threads : omp_get_max_threads()) {}

std::string OpenMpEvaluator::name() const {
  return "openmp(" + std::to_string(threads_) + (threads_ == 1 ? " thread)" : " threads)");
}

void OpenMpEvaluator::evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                               std::vector<double>& fitness, const EvaluationContext& context) {
  fitness.assign(xs.size(), std::numeric_limits<double>::quiet_NaN());
  const long count = static_cast<long>(xs.size());
  if (count == 1 && threads_ > 1) {
    // One individual: no parallel region here; the problem may use the threads itself.
    EvaluationContext own = context;
    own.spare_threads = threads_;
    problem.evaluate_batch(xs, fitness, own);
    return;
  }
  // An exception must not leave an OpenMP region: keep the one of the lowest index, so which
  // one the caller sees does not depend on the thread count, and rethrow after the loop.
  std::exception_ptr first_error;
  long first_error_index = count;
#pragma omp parallel for num_threads(threads_) schedule(dynamic, 1)
  for (long k = 0; k < count; ++k) {
    try {
      const std::vector<std::vector<double>> single{xs[static_cast<std::size_t>(k)]};
      std::vector<double> value(1, std::numeric_limits<double>::quiet_NaN());
      EvaluationContext own = context;
      own.first_individual = context.first_individual + static_cast<std::uint64_t>(k);
      problem.evaluate_batch(single, value, own);
      fitness[static_cast<std::size_t>(k)] = value[0];
    } catch (...) {
#pragma omp critical(motoflex_es_evaluator_error)
      {
        if (k < first_error_index) {
          first_error_index = k;
          first_error = std::current_exception();
        }
      }
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace motoflex_es
