#include "motoflex/fit/fit_spec.hpp"

#include <cmath>
#include <filesystem>

namespace motoflex {
namespace {

namespace fs = std::filesystem;

bool fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

bool one_of(const std::string& value, std::initializer_list<const char*> allowed) {
  for (const char* a : allowed) {
    if (value == a) return true;
  }
  return false;
}

bool strategy_is_valid(const StrategyConfig& s, const std::string& where, std::string* error) {
  if (!one_of(s.kind, {"mu_plus_lambda", "cma_es", "nlopt"})) {
    return fail(error, where + ".kind: expected mu_plus_lambda, cma_es or nlopt");
  }
  for (const std::string* r : {&s.object_recombination, &s.step_recombination}) {
    if (!one_of(*r, {"none", "discrete", "intermediate"})) {
      return fail(error, where + ": recombination must be none, discrete or intermediate");
    }
  }
  if (!one_of(s.algorithm, {"bobyqa", "sbplx", "crs2_lm", "isres", "esch"})) {
    return fail(error, where + ".algorithm: expected bobyqa, sbplx, crs2_lm, isres or esch");
  }
  if (!one_of(s.polish, {"", "bobyqa", "sbplx"})) {
    return fail(error, where + ".polish: expected bobyqa or sbplx");
  }
  if (!(s.initial_step > 0.0) || !(s.sigma > 0.0)) {
    return fail(error, where + ": initial_step and sigma must be positive");
  }
  return true;
}

}  // namespace

bool FitSpec::is_valid(std::string* error) const {
  if (scenario_path.empty()) return fail(error, "scenario: missing");
  if (train_data.empty()) return fail(error, "data: no training logs");
  if (free.empty()) return fail(error, "free: no free parameters");
  for (const FreeParameterSpec& p : free) {
    if (p.pattern.empty()) return fail(error, "free: an entry has no name");
    if (p.lower && p.upper && !(*p.lower < *p.upper)) {
      return fail(error, "free." + p.pattern + ": lower bound must be below the upper bound");
    }
    if (p.log_scale && p.lower && !(*p.lower > 0.0)) {
      return fail(error, "free." + p.pattern + ": a log-scale parameter needs lower > 0");
    }
  }
  if (fixed.size() != fixed_where.size() && !fixed_where.empty()) {
    return fail(error, "fixed: sources do not match the values");
  }
  if (!(fitness_m >= 0.0) || !std::isfinite(fitness_m)) return fail(error, "fitness.m: >= 0");
  if (!(fitness_settle_s >= 0.0)) return fail(error, "fitness.settle_s: must be >= 0");
  if (!(imu_weight >= 0.0)) return fail(error, "fitness.imu_weight: must be >= 0");
  if (!(window_s >= 0.0)) return fail(error, "fitness.window_s: must be >= 0");
  for (const auto& [joint, weight] : joint_weights) {
    if (!(weight >= 0.0)) return fail(error, "fitness.weights." + joint + ": must be >= 0");
  }
  if (!strategy_is_valid(strategy, "strategy", error)) return false;
  if (!strategy_is_valid(loop.refit_strategy, "loop.refit.strategy", error)) return false;
  if (!one_of(polish.method, {"", "none", "lm"})) return fail(error, "polish.method: lm or none");
  if (polish.max_iterations < 1) return fail(error, "polish.max_iterations: must be >= 1");
  if (!(polish.jacobian_step > 0.0 && polish.jacobian_step <= 0.1)) {
    return fail(error, "polish.jacobian_step: must be in (0, 0.1]");
  }
  if (!(budget.max_seconds >= 0.0)) return fail(error, "budget.seconds: must be >= 0");
  if (loop.candidates < 1) return fail(error, "loop.candidates: must be >= 1");
  if (!(loop.min_gain >= 0.0 && loop.min_gain < 1.0)) {
    return fail(error, "loop.min_gain: must be in [0, 1)");
  }
  if (threads < 1) return fail(error, "threads: must be >= 1");
  if (out_dir.empty()) return fail(error, "out: no run folder");
  return true;
}

void apply_fit_overrides(FitSpec& spec, const FitOverrides& overrides) {
  if (overrides.out) spec.out_dir = *overrides.out;
  if (overrides.data) spec.train_data = {{*overrides.data, {"", 0, "--data"}}};
  if (overrides.validation) {
    spec.validation_data = {{*overrides.validation, {"", 0, "--validation"}}};
  }
  if (overrides.threads) spec.threads = *overrides.threads;
  if (overrides.seed) spec.seed = *overrides.seed;
  if (overrides.max_generations) spec.budget.max_generations = *overrides.max_generations;
  if (overrides.max_evaluations) spec.budget.max_evaluations = *overrides.max_evaluations;
  if (overrides.max_seconds) spec.budget.max_seconds = *overrides.max_seconds;
  if (overrides.start_from) spec.start_from = *overrides.start_from;
}

}  // namespace motoflex
