#include "motoflex/fit/fit_session.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "fit_lm_polish.hpp"
#include "fit_outputs.hpp"
#include "fit_run_dir.hpp"
#include "fit_sensitivity.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/excitation_check.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex_es/checkpoint.hpp"
#include "motoflex_es/driver.hpp"
#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/improvement_stall.hpp"
#include "motoflex_es/nlopt_optimizer.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

using Clock = std::chrono::steady_clock;

// Whether a stop of the main strategy is its own convergence test, and in words why.
std::pair<bool, std::string> convergence_of(const motoflex_es::RunSummary& run,
                                            const motoflex_es::Strategy& strategy,
                                            bool interrupted) {
  using motoflex_es::StopReason;
  if (interrupted) return {false, "not converged: interrupted"};
  if (run.reason != motoflex_es::RunStopReason::kStrategy) {
    return {false,
            std::string("not converged: budget (") + motoflex_es::to_string(run.reason) + ")"};
  }
  const StopReason reason = strategy.stop_reason();
  const std::string name = motoflex_es::to_string(reason);
  switch (reason) {
    case StopReason::kTolX:
    case StopReason::kNoEffect:
      return {true, "converged: step size (" + name + ")"};
    case StopReason::kTolFun:
    case StopReason::kOptimizerConverged:
    case StopReason::kTargetReached:
      return {true, "converged: tolerance (" + name + ")"};
    case StopReason::kStagnation:
    case StopReason::kTolStall:
    case StopReason::kRestartsExhausted:
      return {true, "converged: stall (" + name + ")"};
    case StopReason::kEvaluationBudget:
    case StopReason::kMaxIterations:
      return {false, "not converged: budget (" + name + ")"};
    default:
      return {false, "not converged: " + name};
  }
}

// Why budget.stall_evaluations stopped the strategy, in words.
std::string stall_text(const FitBudget& budget, const motoflex_es::ImprovementStall& stall) {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "budget.stall_evaluations: the best fitness %.6g (after %llu evaluations) improved "
                "by less than %g %% in %llu evaluations",
                stall.anchor_fitness(), static_cast<unsigned long long>(stall.anchor_evaluations()),
                100.0 * budget.stall_relative,
                static_cast<unsigned long long>(budget.stall_evaluations));
  return buffer;
}

}  // namespace

std::string FitProgress::line() const {
  char buffer[200];
  if (polish) {
    std::snprintf(buffer, sizeof buffer, "polish (%s): %llu evaluations, best %.6g  %.1f s",
                  polish_algorithm.c_str(), static_cast<unsigned long long>(evaluations),
                  best_fitness, seconds);
  } else {
    std::snprintf(buffer, sizeof buffer,
                  "gen %4llu  evals %7llu  best %.6g  median %.4g  sigma %.3g  early-stopped %llu "
                  " %.1f s",
                  static_cast<unsigned long long>(generation),
                  static_cast<unsigned long long>(evaluations), best_fitness, batch_median,
                  mean_sigma, static_cast<unsigned long long>(stopped_early), seconds);
  }
  return buffer;
}

struct FitSession::State {
  FitConfig config;
  bool resume = false;
  FitProgressCallback progress;
  motoflex_es::Evaluator* evaluator = nullptr;
  const std::atomic<bool>* external_cancel = nullptr;
  std::atomic<bool> cancelled{false};

  bool should_stop() const {
    return cancelled.load() || (external_cancel != nullptr && external_cancel->load());
  }
  void report(const FitProgress& event) const {
    if (progress) progress(event);
  }
};

FitSession FitSession::start(FitConfig config) {
  return FitSession(std::move(config), false);
}

FitSession FitSession::resume(const std::string& run_dir, const FitOverrides& overrides) {
  return FitSession(load_run_config(run_dir, overrides), true);
}

FitSession::FitSession(FitConfig config, bool resume) : state_(std::make_unique<State>()) {
  state_->config = std::move(config);
  state_->resume = resume;
}

FitSession::~FitSession() = default;
FitSession::FitSession(FitSession&&) noexcept = default;
FitSession& FitSession::operator=(FitSession&&) noexcept = default;

void FitSession::set_progress(FitProgressCallback callback) {
  state_->progress = std::move(callback);
}
void FitSession::set_evaluator(motoflex_es::Evaluator* evaluator) {
  state_->evaluator = evaluator;
}
void FitSession::set_cancel_flag(const std::atomic<bool>* flag) {
  state_->external_cancel = flag;
}
void FitSession::cancel() {
  state_->cancelled.store(true);
}
const FitConfig& FitSession::config() const {
  return state_->config;
}

namespace {

std::unique_ptr<motoflex_es::Evaluator> default_evaluator(const FitConfig& config) {
  if (config.threads > 1) return std::make_unique<motoflex_es::OpenMpEvaluator>(config.threads);
  return std::make_unique<motoflex_es::SerialEvaluator>();
}

// Seconds of the run so far: earlier sessions plus this one.
class RunClock {
 public:
  explicit RunClock(double seconds_before) : before_(seconds_before), start_(Clock::now()) {}
  double now() const {
    return before_ + std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  double before_;
  Clock::time_point start_;
};

// What the run's steps need of the session: its progress callback and whether to stop.
struct SessionHooks {
  const FitProgressCallback& progress;
  std::function<bool()> should_stop;
  void report(const FitProgress& event) const {
    if (progress) progress(event);
  }
};

// The main strategy, generation by generation, each one checkpointed; fills the result's stop
// reason and convergence.
void run_main_strategy(const FitConfig& config, motoflex_es::Strategy& strategy,
                       FitProblem& problem, motoflex_es::Evaluator& evaluator, detail::RunDir& dir,
                       detail::RunDirState& saved, const RunClock& clock, const SessionHooks& s,
                       detail::RunResult& result) {
  motoflex_es::Budget budget;
  budget.max_generations = config.budget.max_generations;
  budget.max_evaluations = config.budget.max_evaluations;
  budget.max_seconds = config.budget.max_seconds;
  motoflex_es::ImprovementStall stall(config.budget.stall_evaluations,
                                      config.budget.stall_relative);
  stall.restore(saved.stall_anchor_fitness, saved.stall_anchor_evaluations);
  motoflex_es::RunCallbacks callbacks;
  callbacks.on_generation = [&](const motoflex_es::Strategy& st,
                                const motoflex_es::GenerationReport& report) {
    const double seconds = clock.now();
    const double sigma = detail::mean_sigma(st);
    stall.update(report.best_fitness, report.evaluations);
    saved.stall_anchor_fitness = stall.anchor_fitness();
    saved.stall_anchor_evaluations = stall.anchor_evaluations();
    dir.append_generation(report, sigma, seconds);
    dir.write_checkpoint(st, problem, saved, seconds);
    FitProgress event;
    event.generation = report.generation;
    event.evaluations = report.evaluations;
    event.best_fitness = report.best_fitness;
    event.batch_median = report.batch_median;
    event.mean_sigma = sigma;
    event.stopped_early = problem.stopped_early();
    event.seconds = seconds;
    s.report(event);
    return !s.should_stop() && !stall.stalled();
  };
  // The model a refit extends, before the search (a resumed run has it in its best already).
  if (!config.incumbent_x.empty() && strategy.evaluations() == 0) {
    motoflex_es::evaluate_incumbent(strategy, problem, evaluator, config.incumbent_x);
  }
  const motoflex_es::RunSummary run =
      motoflex_es::run_optimisation(strategy, problem, evaluator, budget, callbacks);
  const bool interrupted = s.should_stop();
  const bool stalled =
      !interrupted && run.reason == motoflex_es::RunStopReason::kCallback && stall.stalled();
  const bool finished =
      !interrupted && (stalled || run.reason == motoflex_es::RunStopReason::kStrategy);
  result.stop_reason =
      interrupted ? std::string("interrupted") : std::string(motoflex_es::to_string(run.reason));
  if (finished) {
    result.stop_reason = std::string("strategy: ") + motoflex_es::to_string(strategy.stop_reason());
    if (!strategy.stop_detail().empty()) result.stop_reason += " (" + strategy.stop_detail() + ")";
  }
  std::tie(result.converged, result.convergence) = convergence_of(run, strategy, interrupted);
  if (stalled) {
    result.stop_reason = stall_text(config.budget, stall);
    result.converged = true;
    result.convergence = "converged: stall (" + result.stop_reason + ")";
  }
  // Only a strategy that stopped by itself is finished; a budget stop can be resumed with a
  // larger budget.
  if (finished) {
    saved.main_done = true;
    saved.converged = result.converged;
    saved.convergence = result.convergence;
    dir.write_checkpoint(strategy, problem, saved, clock.now());
  }
}

// Optional local polish of the best point (NLopt keeps its state inside the library, so a
// killed polish starts again from the main strategy's best).
void run_polish(const FitConfig& config, const motoflex_es::Strategy& strategy, FitProblem& problem,
                const RunClock& clock, const SessionHooks& hooks, detail::RunResult& result) {
  motoflex_es::NloptOptions options;
  options.algorithm = config.strategy.polish == "sbplx" ? motoflex_es::NloptAlgorithm::kSbplx
                                                        : motoflex_es::NloptAlgorithm::kBobyqa;
  options.start_point = result.best_x;
  options.initial_step_relative = 0.02;
  options.max_evaluations = config.strategy.polish_evaluations;
  options.seed = config.seed;
  motoflex_es::NloptOptimizer polish(strategy.bounds(), options);
  motoflex_es::SerialEvaluator serial;
  motoflex_es::Budget budget;
  budget.max_evaluations = config.strategy.polish_evaluations;
  const auto run = motoflex_es::run_optimisation(polish, problem, serial, budget);
  result.polish_evaluations = run.evaluations;
  if (polish.best_fitness() < result.best_fitness) {
    result.best_fitness = polish.best_fitness();
    result.best_x = polish.best_x();
  }
  FitProgress event;
  event.polish = true;
  event.polish_algorithm = config.strategy.polish;
  event.evaluations = result.polish_evaluations;
  event.best_fitness = result.best_fitness;
  event.seconds = clock.now();
  hooks.report(event);
}

// The `polish: {method: lm}` finish: kept only if it lowers the fitness.
// LM reports each iteration, stops after the iteration in which the session is cancelled, and
// gets what is left of a `budget: {seconds}` (none left: it does not run).
void run_lm_polish(const FitConfig& config, const RunClock& clock, const SessionHooks& hooks,
                   detail::RunResult& result) {
  const double seconds = clock.now();
  detail::LmPolishHooks lm_hooks;
  lm_hooks.should_stop = hooks.should_stop;
  if (config.budget.max_seconds > 0.0) {
    lm_hooks.max_seconds = config.budget.max_seconds - seconds;
    if (lm_hooks.max_seconds <= 0.0) {
      result.lm.x = result.best_x;
      result.lm.fitness_before = result.lm.fitness_after = result.best_fitness;
      result.lm.termination = "not run: the time budget was spent";
      result.lm_ran = true;
      return;
    }
  }
  lm_hooks.on_iteration = [&](const detail::LmIteration& step) {
    FitProgress event;
    event.polish = true;
    event.polish_algorithm = "lm iteration " + std::to_string(step.iteration);
    event.evaluations = step.rollouts;
    event.best_fitness = step.fitness;
    event.seconds = seconds + step.seconds;
    hooks.report(event);
  };
  lm_hooks.on_scan_move = [&](const detail::FlatScanMove& move, std::uint64_t rollouts) {
    FitProgress event;
    event.polish = true;
    char values[64];
    std::snprintf(values, sizeof values, " %.4g -> %.4g", move.from, move.to);
    event.polish_algorithm = "flat scan: " + move.parameter + values;
    event.evaluations = rollouts;
    event.best_fitness = move.fitness_after;
    event.seconds = clock.now();
    hooks.report(event);
  };
  result.lm = detail::lm_polish(config, result.best_x, result.best_fitness, lm_hooks);
  result.lm_ran = true;
  result.polish_evaluations += result.lm.rollouts;
  if (result.lm.used) {
    result.best_x = result.lm.x;
    result.best_fitness = result.lm.fitness_after;
  }
  FitProgress event;
  event.polish = true;
  event.polish_algorithm = "lm, " + std::to_string(result.lm.iterations) + " iterations, " +
                           (result.lm.used ? "kept" : "not better");
  event.evaluations = result.lm.rollouts;
  event.best_fitness = result.best_fitness;
  event.seconds = clock.now();
  hooks.report(event);
}

}  // namespace

FitSummary FitSession::run() {
  State& s = *state_;
  const FitConfig& config = s.config;
  auto strategy = make_strategy(config);
  FitProblem problem(config);
  detail::RunDir dir(config);
  detail::RunDirState saved = s.resume ? dir.resume(*strategy, problem) : dir.start();
  dir.write_run_json();
  std::unique_ptr<motoflex_es::Evaluator> own_evaluator;
  motoflex_es::Evaluator* evaluator = s.evaluator;
  if (evaluator == nullptr) {
    own_evaluator = default_evaluator(config);
    evaluator = own_evaluator.get();
  }
  const RunClock clock(saved.seconds_before);
  const SessionHooks hooks{s.progress, [&s] { return s.should_stop(); }};

  if (!s.resume) {
    // Said before the first generation: a joint the logs leave still wastes the whole budget.
    for (const std::string& warning :
         excitation_warnings(config.train->model(), config.train->cases())) {
      std::fprintf(stderr, "motoflex: warning: %s\n", warning.c_str());
    }
  }
  detail::RunResult result;
  result.strategy = strategy->name();
  result.evaluator = evaluator->name();
  if (!saved.main_done) {
    run_main_strategy(config, *strategy, problem, *evaluator, dir, saved, clock, hooks, result);
  } else {
    result.stop_reason = "finished before resume";
    result.converged = saved.converged;
    result.convergence = saved.convergence;
  }
  result.best_fitness = strategy->best_fitness();
  result.best_x = strategy->best_x();
  if (!s.should_stop() && !config.strategy.polish.empty() && !result.best_x.empty()) {
    run_polish(config, *strategy, problem, clock, hooks, result);
  }
  if (!s.should_stop() && config.polish.lm() && !result.best_x.empty()) {
    run_lm_polish(config, clock, hooks, result);
  }
  if (!s.should_stop() && config.polish.reports_uncertainty() && !result.best_x.empty()) {
    result.uncertainty = detail::fit_uncertainty(config, result.best_x);
  }
  if (!s.should_stop() && !result.best_x.empty()) {
    result.sensitivity = detail::fitness_sensitivity(problem, *evaluator, result.best_x);
  }
  result.generations = strategy->generation();
  result.evaluations = strategy->evaluations() + result.polish_evaluations;
  if (s.should_stop()) result.stop_reason = "interrupted";
  result.seconds = clock.now();
  return detail::write_fit_outputs(config, problem, result);
}

FitConfig load_run_config(const std::string& run_dir, const FitOverrides& overrides) {
  const fs::path run_json = fs::path(run_dir) / "run.json";
  std::ifstream in(run_json);
  if (!in) {
    // A fit stopped before it wrote run.json (killed, or the disk full) leaves its lock file.
    const bool started = fs::exists(fs::path(run_dir) / ".motoflex.lock");
    throw InputError(run_json.string(), 0, "",
                     started ? "missing: the fit stopped before it wrote its run files; start it "
                               "again with `motoflex fit CONFIG --out " +
                                   run_dir + "`"
                             : "not a fit run folder (no run.json)");
  }
  nlohmann::json run;
  try {
    in >> run;
  } catch (const nlohmann::json::exception& error) {
    throw InputError(run_json.string(), 0, "", std::string("corrupt: ") + error.what());
  }
  if (!run.contains("fit") || !run["fit"].is_string()) {
    throw InputError(run_json.string(), 0, "fit", "missing");
  }
  FitOverrides merged = overrides_from_json(run.value("overrides", nlohmann::json::object()));
  // Threads and the budget may change on resume; the rest is the run's.
  if (overrides.threads) merged.threads = overrides.threads;
  if (overrides.max_generations) merged.max_generations = overrides.max_generations;
  if (overrides.max_evaluations) merged.max_evaluations = overrides.max_evaluations;
  if (overrides.max_seconds) merged.max_seconds = overrides.max_seconds;
  merged.out = fs::absolute(run_dir).lexically_normal().string();
  return load_fit_config(run["fit"].get<std::string>(), merged);
}

}  // namespace motoflex
