#pragma once

// Internal to FitSession: the `polish: {method: lm}` finish — Levenberg–Marquardt (Ceres) on
// the fit's residual vector (fit_residuals.hpp) from the strategy's best point, within the
// bounds, and the parameter covariance at the final point (parameter_covariance.hpp).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "flat_direction_scan.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/parameter_covariance.hpp"
#include "motoflex/fit/residual_autocorrelation.hpp"

namespace motoflex::detail {

struct LmPolishResult {
  std::vector<double> x;  // LM's final point (search coordinates)
  double fitness_before = 0.0;
  double fitness_after = 0.0;  // F at x, measured as the strategy measures it
  bool used = false;           // fitness_after < fitness_before: x replaces the best point
  std::uint64_t rollouts = 0;  // passes over all training logs (residuals and Jacobians)
  int iterations = 0;
  std::string termination;  // Ceres's message (of the last LM run)
  // `polish.flat_scan`: the parameters the scans moved, in order (LM runs again after each
  // scan that moves one, with the iterations left).
  std::vector<FlatScanMove> flat_scan_moves;
};

// One finished LM iteration (Ceres's iteration 0 is the start point).
struct LmIteration {
  int iteration = 0;
  double fitness = 0.0;  // F at LM's current point (2 × Ceres's cost; a rejected step keeps it)
  std::uint64_t rollouts = 0;  // passes over all training logs so far
  double seconds = 0.0;        // LM's wall time so far
};

// How LM reports and ends early. Each iteration costs a Jacobian (2p passes over the logs), so
// a long polish says where it is, stops after the iteration in which `should_stop` turns true
// (Ctrl-C, a cancelled session) and within `max_seconds` (> 0; the fit's remaining time budget).
struct LmPolishHooks {
  std::function<void(const LmIteration&)> on_iteration;
  std::function<bool()> should_stop;
  // A flat scan's move, with the passes over the logs the polish has made so far.
  std::function<void(const FlatScanMove&, std::uint64_t rollouts)> on_scan_move;
  double max_seconds = 0.0;  // 0: no limit
};

// LM from `start` (F = `start_fitness`) within the bounds, up to polish.max_iterations
// iterations in all; with polish.flat_scan, the parameters whose Jacobian column is zero at LM's
// end are scanned (flat_direction_scan.hpp) and LM goes on from a scan that lowers F, until no
// column is flat, no scan helps or the iterations are spent.
LmPolishResult lm_polish(const FitConfig& config, const std::vector<double>& start,
                         double start_fitness, const LmPolishHooks& hooks = {});

struct FitUncertainty {
  LeastSquaresCovariance search;            // in the strategy's coordinates (log where searched so)
  ResidualAutocorrelation autocorrelation;  // of r at x: the covariance's inflation κ
  // Per parameter: r's departure from linear over the Jacobian's ±h (FitResiduals::jacobian).
  std::vector<double> nonlinearity;
  std::uint64_t rollouts = 0;
  bool computed = false;  // false: a rollout at x failed, or fewer residuals than parameters
};

// κσ²(JᵀJ)⁻¹ at x with a central finite-difference Jacobian, κ from the autocorrelation of r(x).
FitUncertainty fit_uncertainty(const FitConfig& config, const std::vector<double>& x);

}  // namespace motoflex::detail
