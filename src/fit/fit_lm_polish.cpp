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
// residuals; the Jacobian by finite differences through the rollout (`polish.jacobian`).
class RolloutCost final : public ceres::CostFunction {
 public:
  RolloutCost(const FitResiduals& residuals, double step, FiniteDifferences scheme,
              std::atomic<std::uint64_t>& rollouts)
      : residuals_(residuals), step_(step), scheme_(scheme), rollouts_(rollouts) {
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
      rollouts_ += residuals_.jacobian(x, r0, step_, j, scheme_, nullptr);
      std::copy(j.begin(), j.end(), jacobians[0]);
      last_jacobian_x_ = x;
      last_jacobian_ = std::move(j);
    }
    return true;
  }

  // The last Jacobian Ceres asked for and its point (Ceres asks at each point it accepts).
  const std::vector<double>& last_jacobian_x() const { return last_jacobian_x_; }
  const std::vector<double>& last_jacobian() const { return last_jacobian_; }

 private:
  const FitResiduals& residuals_;
  double step_;
  FiniteDifferences scheme_;
  std::atomic<std::uint64_t>& rollouts_;
  mutable std::vector<double> last_jacobian_x_;
  mutable std::vector<double> last_jacobian_;
};

// Reports every iteration and ends the solve when the hooks say so. Ceres's cost is ½‖r‖² and
// ‖r‖² is the fitness (fit_residuals.hpp).
class ProgressCallback final : public ceres::IterationCallback {
 public:
  // `first_iteration`: the number reported for this run's iteration 0 (the count of earlier LM
  // runs of this polish goes on); a later run's iteration 0, the scan's point, is reported only
  // when `report_start`.
  ProgressCallback(const LmPolishHooks& hooks, const std::atomic<std::uint64_t>& rollouts,
                   std::chrono::steady_clock::time_point start, int first_iteration,
                   bool report_start)
      : hooks_(hooks),
        rollouts_(rollouts),
        start_(start),
        first_iteration_(first_iteration),
        report_start_(report_start) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    // A rejected step reports the cost of the point it tried; LM stays where it was.
    if (summary.iteration == 0 || summary.step_is_successful) {
      best_fitness_ = std::min(best_fitness_, 2.0 * summary.cost);
    }
    if (hooks_.on_iteration && (summary.iteration > 0 || report_start_)) {
      LmIteration event;
      event.iteration = first_iteration_ + summary.iteration;
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
  int first_iteration_ = 0;
  bool report_start_ = true;
  double best_fitness_ = std::numeric_limits<double>::infinity();
};

// One Ceres LM run from x (left at its best accepted point, clamped into the bounds) and the
// Jacobian at that point.
struct LmRun {
  int iterations = 0;  // Ceres's iterations after its iteration 0
  std::string termination;
  std::vector<double> jacobian;  // row-major N x p at x
};

LmRun run_lm(const FitConfig& config, const FitResiduals& residuals, std::vector<double>& x,
             int max_iterations, double max_seconds, const LmPolishHooks& hooks,
             std::atomic<std::uint64_t>& rollouts, std::chrono::steady_clock::time_point start,
             int first_iteration, bool report_start) {
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  RolloutCost cost(residuals, config.polish.jacobian_step, config.polish.lm_jacobian, rollouts);
  problem.AddResidualBlock(&cost, nullptr, x.data());
  const std::vector<double> lower = config.space->lower(), upper = config.space->upper();
  for (std::size_t i = 0; i < x.size(); ++i) {
    problem.SetParameterLowerBound(x.data(), static_cast<int>(i), lower[i]);
    problem.SetParameterUpperBound(x.data(), static_cast<int>(i), upper[i]);
  }
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = max_iterations;
  options.num_threads = 1;  // the Jacobian's rollouts are the parallel part
  // No projected line search at the bounds: each of its steps would cost a Jacobian (2p
  // rollout sets); the trust region alone stays within them.
  options.max_num_line_search_step_size_iterations = 0;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  if (max_seconds > 0.0) options.max_solver_time_in_seconds = max_seconds;
  ProgressCallback progress(hooks, rollouts, start, first_iteration, report_start);
  options.callbacks.push_back(&progress);
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  LmRun run;
  run.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  run.termination = summary.message;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], lower[i], upper[i]);
  if (cost.last_jacobian_x() == x) run.jacobian = cost.last_jacobian();
  return run;
}

// F at x as the strategy measures it (infinite where a rollout fails).
double measured_fitness(const FitConfig& config, const std::vector<double>& x) {
  try {
    return config.train
        ->evaluate(config.space->apply(x), std::numeric_limits<double>::infinity(), nullptr,
                   config.threads)
        .fitness;
  } catch (const std::exception&) {
    return std::numeric_limits<double>::infinity();
  }
}

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
  const auto clock_start = std::chrono::steady_clock::now();
  const auto seconds_left = [&] {
    if (hooks.max_seconds <= 0.0) return 0.0;  // no limit
    const double spent =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
    return std::max(hooks.max_seconds - spent, 1e-3);
  };
  std::vector<double> x = start;
  int iterations_left = static_cast<int>(config.polish.max_iterations);
  // Each scan moves one parameter and lowers F, so the rounds end; bound them all the same.
  for (int round = 0; round <= static_cast<int>(residuals.dimension()); ++round) {
    // result.iterations counts the reported iterations: the first run's iteration 0 and every
    // accepted or rejected step after it.
    const bool first_run = round == 0;
    LmRun run = run_lm(config, residuals, x, iterations_left, seconds_left(), hooks, rollouts,
                       clock_start, first_run ? 0 : result.iterations - 1, first_run);
    result.iterations += run.iterations + (first_run ? 1 : 0);
    result.termination = run.termination;
    iterations_left -= run.iterations;
    const double fitness = measured_fitness(config, x);
    ++rollouts;
    if (fitness < result.fitness_after) {
      result.x = x;
      result.fitness_after = fitness;
    }
    const bool out_of_time =
        hooks.max_seconds > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count() >=
            hooks.max_seconds;
    // A scan may still move a parameter when LM has no iterations left; LM then stops.
    if (config.polish.flat_scan == 0 || out_of_time || (hooks.should_stop && hooks.should_stop())) {
      break;
    }
    // The scan starts from LM's point when LM's point is the best, with its Jacobian there.
    if (x != result.x) break;
    std::vector<double> jacobian = std::move(run.jacobian);
    if (jacobian.empty()) {
      std::vector<double> r0(residuals.size());
      ++rollouts;
      if (!residuals.evaluate(x, r0.data())) break;
      rollouts += residuals.jacobian(x, r0, config.polish.jacobian_step, jacobian,
                                     config.polish.lm_jacobian, nullptr);
    }
    const std::vector<std::size_t> flat =
        flat_columns(jacobian, residuals.size(), residuals.dimension());
    if (flat.empty()) break;
    FlatScanResult scan = scan_flat_directions(
        *config.space, x, result.fitness_after, flat, config.polish.flat_scan,
        [&config](const std::vector<double>& at) { return measured_fitness(config, at); });
    rollouts += scan.rollouts;
    if (!scan.move) break;
    if (hooks.on_scan_move) hooks.on_scan_move(*scan.move, rollouts.load());
    result.flat_scan_moves.push_back(std::move(*scan.move));
    x = scan.x;
    result.x = scan.x;
    result.fitness_after = scan.fitness;
    if (iterations_left <= 0) break;
  }
  result.rollouts = rollouts.load();
  result.used = result.fitness_after < start_fitness;
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
  // Central whatever LM used: computed once, and the intervals should not carry an O(h) error.
  out.rollouts += residuals.jacobian(x, r0, config.polish.jacobian_step, j,
                                     FiniteDifferences::kCentral, &out.nonlinearity);
  double rss = 0.0;
  for (const double r : r0) rss += r * r;
  out.autocorrelation =
      residual_autocorrelation(r0, residuals.frames_per_case(), residuals.channels());
  out.search = least_squares_covariance(j, n, p, rss, out.autocorrelation.inflation);
  out.computed = true;
  return out;
}

}  // namespace motoflex::detail
