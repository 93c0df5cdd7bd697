#pragma once

// FitSummary: what a finished (or stopped) fit reports, modelled on Ceres's Solver::Summary:
// brief_report() is one line, full_report() the table a user reads, to_json() is summary.json.

#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motoflex/fit/residual_autocorrelation.hpp"

namespace motoflex {

struct FittedParameter {
  std::string name;  // as the fit names it (may be a pattern for a tie)
  std::string unit;
  double start = 0.0;
  double lower = 0.0;
  double upper = 0.0;
  double value = 0.0;
  bool log_scale = false;
  // Relative fitness change per bound-width around the best point (finite differences of 1 %
  // of the range; < 0: not measured). Below 0.1 the training data cannot determine the value.
  double sensitivity = -1.0;
  bool undetermined() const { return sensitivity >= 0.0 && sensitivity < 0.1; }
  // 95 % confidence interval (model units) and standard error from σ²(JᵀJ)⁻¹ (`polish:` with
  // covariance; NaN when not computed, ±inf when the data do not determine the parameter).
  double standard_error = std::numeric_limits<double>::quiet_NaN();
  double ci_lower = std::numeric_limits<double>::quiet_NaN();
  double ci_upper = std::numeric_limits<double>::quiet_NaN();
  // The share of [lower, upper] (search coordinates) the interval covers; NaN when not computed.
  double ci_share_of_bounds = std::numeric_limits<double>::quiet_NaN();
  // How far the residual is from linear in this parameter over the Jacobian's step ±h:
  // ‖d₊ + d₋‖/‖d₊ − d₋‖ (d± = r(x ± h) − r(x)); NaN when not measured. Above kNonlinearShare
  // the second-order change is at least half the first-order one (near 1 for a chaotic walk,
  // where any small change sends the late trajectory elsewhere): the linearisation behind the
  // interval does not hold at that scale, and the interval says nothing.
  double nonlinearity = std::numeric_limits<double>::quiet_NaN();
  bool nonlinear() const { return nonlinearity > kNonlinearShare; }
  static constexpr double kNonlinearShare = 0.5;
  // The interval spans most (> kUnidentifiedShare) of the bounds, or it rests on a linearisation
  // that does not hold: the data do not identify the parameter (as far as the interval shows).
  bool unidentified() const { return ci_share_of_bounds > kUnidentifiedShare || nonlinear(); }
  static constexpr double kUnidentifiedShare = 0.5;
  // Where the value sits between its bounds, 0…1 (log scale where searched so); a value at a
  // bound (< 1 % or > 99 %) usually means the bounds cut the optimum off.
  double bound_fraction() const;
};

struct FitSummary {
  std::string name;
  std::string run_dir;
  std::string strategy;   // e.g. "mu_plus_lambda(10+40, kappa 3)"
  std::string evaluator;  // e.g. "openmp(2 threads)"
  // Why the run ended: a budget ("max_generations"), "interrupted", or the strategy's own
  // "strategy: tol_fun (...)".
  std::string stop_reason;
  // True when the strategy stopped by its own convergence test (tolerance on x or f, stall,
  // target, a finished local optimiser); false for a budget, an interrupt or a failure.
  bool converged = false;
  std::string convergence;  // "converged: tolerance (tol_fun)" / "not converged: budget (...)"
  double best_fitness = 0.0;
  std::uint64_t evaluations = 0;  // main strategy + polish
  std::uint64_t generations = 0;
  std::uint64_t polish_evaluations = 0;
  // `polish: {method: lm}`: what LM did (fitness before → after, whether it was kept).
  std::string polish_method;  // "" (none), "bobyqa", "sbplx", "lm"
  double fitness_before_polish = std::numeric_limits<double>::quiet_NaN();
  bool polish_used = false;
  // κσ²(JᵀJ)⁻¹ of the free parameters in model units (delta method on log-scale ones) and its
  // correlation matrix; empty when not computed. κ = (1 + ρ)/(1 − ρ) for the residuals' lag-1
  // autocorrelation ρ (residual_autocorrelation.hpp).
  std::vector<std::vector<double>> covariance;
  std::vector<std::vector<double>> correlation;
  ResidualAutocorrelation residual_autocorrelation;  // ρ, κ and N_eff of the covariance
  std::size_t residuals = 0;                         // N
  double seconds = 0.0;                              // wall time over all sessions of the run
  std::vector<FittedParameter> parameters;
  double train_rms_deg = 0.0;
  double validation_rms_deg = -1.0;  // < 0: no validation logs
  std::uint64_t individuals_stopped_early = 0;
  std::uint64_t frames_simulated = 0;
  std::uint64_t frames_saved = 0;
  // Candidates the model rejected (a parameter outside what the model accepts), scored +inf.
  std::uint64_t invalid_candidates = 0;
  std::vector<std::string> invalid_reasons;  // up to 5 distinct, sorted
  nlohmann::ordered_json details;  // summary.json as written (per-joint and per-log errors, ...)

  // "nao_quick: max_generations (not converged) after 3 generations, 36 evaluations: best
  // fitness 8.09e-06, train RMS 1.2 deg, validation RMS 1.4 deg (23.5 s)".
  std::string brief_report() const;
  // The brief line, then the parameter table (start, fitted, bounds, position in the bounds),
  // errors per log and the early-termination savings.
  std::string full_report() const;
  // The confidence-interval table and the strongest correlations ("" without covariance).
  std::string uncertainty_report(std::size_t name_width = 10) const;
};

}  // namespace motoflex
