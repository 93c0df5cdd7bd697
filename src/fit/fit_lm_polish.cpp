#include "fit_lm_polish.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <limits>

#include "fit_residuals.hpp"

namespace motoflex::detail {
namespace {

// The residual block of the whole fit: one parameter block (the p search coordinates), N
// residuals; the Jacobian by central differences through the rollout.
class RolloutCost final : public ceres::CostFunction {
 public:
  RolloutCost(const FitResiduals& residuals, double step, std::atomic<std::uint64_t>& rollouts)
      : residuals_(residuals), step_(step), rollouts_(rollouts) {
    set_num_residuals(static_cast<int>(residuals.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<std::int32_t>(residuals.dimension()));
  }

  bool Evaluate(double const* const* parameters, double* out, double** jacobians) const override {
    const std::size_t p = residuals_.dimension(), n = residuals_.size();
    const std::vector<double> x(parameters[0], parameters[0] + p);
    ++rollouts_;
    if (!residuals_.evaluate(x, out)) return false;  // Ceres then shrinks the step
    if (jacobians != nullptr && jacobians[0] != nullptr) {
      const std::vector<double> r0(out, out + n);
      std::vector<double> j;
      rollouts_ += residuals_.jacobian(x, r0, step_, j);
      std::copy(j.begin(), j.end(), jacobians[0]);
    }
    return true;
  }

 private:
  const FitResiduals& residuals_;
  double step_;
  std::atomic<std::uint64_t>& rollouts_;
};

// Reports every iteration and ends the solve when the hooks say so. Ceres's cost is ½‖r‖² and
// ‖r‖² is the fitness (fit_residuals.hpp).
class ProgressCallback final : public ceres::IterationCallback {
 public:
  ProgressCallback(const LmPolishHooks& hooks, const std::atomic<std::uint64_t>& rollouts)
      : hooks_(hooks), rollouts_(rollouts), start_(std::chrono::steady_clock::now()) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    // A rejected step reports the cost of the point it tried; LM stays where it was.
    if (summary.iteration == 0 || summary.step_is_successful) {
      best_fitness_ = std::min(best_fitness_, 2.0 * summary.cost);
    }
    if (hooks_.on_iteration) {
      LmIteration event;
      event.iteration = summary.iteration;
      event.fitness = best_fitness_;
      event.rollouts = rollouts_.load();
      event.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      hooks_.on_iteration(event);
    }
    if (hooks_.should_stop && hooks_.should_stop()) return ceres::SOLVER_TERMINATE_SUCCESSFULLY;
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const LmPolishHooks& hooks_;
  const std::atomic<std::uint64_t>& rollouts_;
  std::chrono::steady_clock::time_point start_;
  double best_fitness_ = std::numeric_limits<double>::infinity();
};

}  // namespace

LmPolishResult lm_polish(const FitConfig& config, const std::vector<double>& start,
                         double start_fitness, const LmPolishHooks& hooks) {
  const FitResiduals residuals(config, config.threads);
  LmPolishResult result;
  result.x = start;
  result.fitness_before = start_fitness;
  result.fitness_after = start_fitness;
  if (residuals.size() <= residuals.dimension()) {
    result.termination = "not run: fewer residuals than parameters";
    return result;
  }
  std::atomic<std::uint64_t> rollouts{0};
  std::vector<double> x = start;
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  problem.AddResidualBlock(new RolloutCost(residuals, config.polish.jacobian_step, rollouts),
                           nullptr, x.data());
  const std::vector<double> lower = config.space->lower(), upper = config.space->upper();
  for (std::size_t i = 0; i < x.size(); ++i) {
    problem.SetParameterLowerBound(x.data(), static_cast<int>(i), lower[i]);
    problem.SetParameterUpperBound(x.data(), static_cast<int>(i), upper[i]);
  }
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = static_cast<int>(config.polish.max_iterations);
  options.num_threads = 1;  // the Jacobian's rollouts are the parallel part
  // No projected line search at the bounds: each of its steps would cost a Jacobian (2p
  // rollout sets); the trust region alone stays within them.
  options.max_num_line_search_step_size_iterations = 0;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  if (hooks.max_seconds > 0.0) options.max_solver_time_in_seconds = hooks.max_seconds;
  ProgressCallback progress(hooks, rollouts);
  options.callbacks.push_back(&progress);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.iterations = static_cast<int>(summary.iterations.size());
  result.termination = summary.message;
  // Ceres leaves the best accepted point in x; measure it as the strategy does.
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], lower[i], upper[i]);
  const double no_threshold = std::numeric_limits<double>::infinity();
  double fitness = no_threshold;
  try {
    fitness = config.train->evaluate(config.space->apply(x), no_threshold, nullptr, config.threads)
                  .fitness;
  } catch (const std::exception&) {
    fitness = std::numeric_limits<double>::infinity();
  }
  ++rollouts;
  result.rollouts = rollouts.load();
  if (fitness < start_fitness) {
    result.x = x;
    result.fitness_after = fitness;
    result.used = true;
  }
  return result;
}

FitUncertainty fit_uncertainty(const FitConfig& config, const std::vector<double>& x) {
  const FitResiduals residuals(config, config.threads);
  FitUncertainty out;
  const std::size_t n = residuals.size(), p = residuals.dimension();
  if (n <= p) return out;
  std::vector<double> r0(n);
  out.rollouts = 1;
  if (!residuals.evaluate(x, r0.data())) return out;
  std::vector<double> j;
  out.rollouts += residuals.jacobian(x, r0, config.polish.jacobian_step, j);
  double rss = 0.0;
  for (const double r : r0) rss += r * r;
  out.search = least_squares_covariance(j, n, p, rss);
  out.computed = true;
  return out;
}

}  // namespace motoflex::detail
