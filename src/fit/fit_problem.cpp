#include <atomic>
#include <limits>
#include <stdexcept>

#include "motoflex/core/error.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex/sim/ode_runtime.hpp"
#include "motoflex_es/cma_es.hpp"
#include "motoflex_es/mu_plus_lambda.hpp"
#include "motoflex_es/nlopt_optimizer.hpp"

namespace motoflex {
namespace {

motoflex_es::Recombination recombination(const std::string& text) {
  if (text == "none") return motoflex_es::Recombination::kNone;
  if (text == "discrete") return motoflex_es::Recombination::kDiscrete;
  return motoflex_es::Recombination::kIntermediate;
}

motoflex_es::NloptAlgorithm nlopt_algorithm(const std::string& text) {
  if (text == "sbplx") return motoflex_es::NloptAlgorithm::kSbplx;
  if (text == "crs2_lm") return motoflex_es::NloptAlgorithm::kCrs2Lm;
  if (text == "isres") return motoflex_es::NloptAlgorithm::kIsres;
  if (text == "esch") return motoflex_es::NloptAlgorithm::kEsch;
  return motoflex_es::NloptAlgorithm::kBobyqa;
}

void check_options(bool ok, const std::string& why, const std::string& path) {
  if (!ok) throw InputError(path, 0, "strategy", why);
}

}  // namespace

FitProblem::FitProblem(const FitConfig& config) : config_(config) {}

std::size_t FitProblem::dimension() const {
  return config_.space->dimension();
}

motoflex_es::Bounds FitProblem::bounds() const {
  return {config_.space->lower(), config_.space->upper()};
}

void FitProblem::set_counters(std::uint64_t stopped, std::uint64_t simulated, std::uint64_t saved,
                              std::uint64_t invalid, const std::vector<std::string>& reasons) {
  stopped_early_ = stopped;
  frames_simulated_ = simulated;
  frames_saved_ = saved;
  invalid_candidates_ = invalid;
  const std::lock_guard<std::mutex> lock(reasons_mutex_);
  invalid_reasons_.clear();
  for (const auto& reason : reasons) {
    if (invalid_reasons_.size() < kMaxInvalidReasons) invalid_reasons_.insert(reason);
  }
}

std::vector<std::string> FitProblem::invalid_reasons() const {
  const std::lock_guard<std::mutex> lock(reasons_mutex_);
  return {invalid_reasons_.begin(), invalid_reasons_.end()};
}

void FitProblem::note_invalid(const std::string& reason) {
  std::atomic_ref<std::uint64_t>(invalid_candidates_).fetch_add(1);
  const std::lock_guard<std::mutex> lock(reasons_mutex_);
  invalid_reasons_.insert(reason);
  // Keep the first reasons in sorted order: the same set for any evaluation order.
  while (invalid_reasons_.size() > kMaxInvalidReasons)
    invalid_reasons_.erase(--invalid_reasons_.end());
}

std::vector<std::uint64_t> FitProblem::counters() const {
  return {stopped_early_, frames_simulated_, frames_saved_, invalid_candidates_};
}

void FitProblem::add_counters(const std::vector<std::uint64_t>& increments) {
  if (increments.size() != 3 && increments.size() != 4) {
    throw std::invalid_argument("FitProblem: 3 or 4 counters expected");
  }
  stopped_early_ += increments[0];
  frames_simulated_ += increments[1];
  frames_saved_ += increments[2];
  if (increments.size() == 4) invalid_candidates_ += increments[3];
}

void FitProblem::evaluate_batch(const std::vector<std::vector<double>>& xs,
                                std::vector<double>& fitness,
                                const motoflex_es::EvaluationContext& context) {
  ensure_ode_ready();  // this may be a worker thread of the evaluator
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double threshold = config_.early_termination ? context.stop_threshold
                                                       : std::numeric_limits<double>::infinity();
    FitnessBreakdown result;
    try {
      result = config_.train->evaluate(config_.space->apply(xs[k]), threshold, nullptr,
                                       context.spare_threads);
    } catch (const std::bad_alloc&) {
      throw;  // the machine, not the candidate
    } catch (const std::exception& error) {
      // A candidate the model rejects is the worst score, never the end of the fit.
      fitness[k] = std::numeric_limits<double>::infinity();
      note_invalid(error.what());
      continue;
    }
    fitness[k] = result.fitness;
    for (const auto& c : result.cases) {
      if (c.end == RolloutEnd::kModelError) {
        note_invalid(c.end_detail);
        break;
      }
    }
    std::uint64_t simulated = 0, requested = 0;
    for (const auto& c : result.cases) simulated += c.frames;
    for (const auto& c : config_.train->cases()) requested += c.commands.frames();
    // Statistics only (they do not feed back into the run); several threads may add at once.
    std::atomic_ref<std::uint64_t>(frames_simulated_).fetch_add(simulated);
    if (result.stopped_early) {
      std::atomic_ref<std::uint64_t>(stopped_early_).fetch_add(1);
      std::atomic_ref<std::uint64_t>(frames_saved_).fetch_add(requested - simulated);
    }
  }
}

std::unique_ptr<motoflex_es::Strategy> make_strategy(const FitConfig& config) {
  const motoflex_es::Bounds bounds{config.space->lower(), config.space->upper()};
  const StrategyConfig& s = config.strategy;
  std::string why;
  if (s.kind == "mu_plus_lambda") {
    motoflex_es::MuPlusLambdaOptions options;
    options.mu = s.mu;
    options.lambda = s.lambda;
    options.kappa = s.kappa == 0 ? motoflex_es::kUnlimitedLifetime : s.kappa;
    options.rho = s.rho;
    options.object_recombination = recombination(s.object_recombination);
    options.step_recombination = recombination(s.step_recombination);
    options.initial_step_relative = s.initial_step;
    options.start_point = config.space->start();
    options.seed = config.seed;
    options.racing = s.racing;
    options.race_chunk = s.race_chunk;
    check_options(options.is_valid(&why), why, config.path);
    return std::make_unique<motoflex_es::MuPlusLambda>(bounds, options);
  }
  if (s.kind == "cma_es") {
    motoflex_es::CmaEsOptions options;
    options.start_point = config.space->start();
    options.initial_sigma_relative = s.sigma;
    options.population_size = s.population;
    options.max_restarts = s.restarts;
    options.active = s.active;
    options.pooled_negative_tail = s.pooled_negative_tail;
    options.racing = s.racing;
    options.seed = config.seed;
    check_options(options.is_valid(&why), why, config.path);
    return std::make_unique<motoflex_es::CmaEs>(bounds, options);
  }
  motoflex_es::NloptOptions options;
  options.algorithm = nlopt_algorithm(s.algorithm);
  options.start_point = config.space->start();
  options.population = s.population;
  options.seed = config.seed;
  // NLopt's global algorithms only stop at their own evaluation limit: the fit's budget.
  options.max_evaluations = config.budget.max_evaluations;
  if (!motoflex_es::is_local(options.algorithm) && options.max_evaluations == 0) {
    throw InputError(config.path, 0, "budget.evaluations",
                     "required for the global NLopt algorithm " + s.algorithm +
                         " (NLopt would run indefinitely)");
  }
  check_options(options.is_valid(&why), why, config.path);
  return std::make_unique<motoflex_es::NloptOptimizer>(bounds, options);
}

}  // namespace motoflex
