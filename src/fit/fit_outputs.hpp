#pragma once

// Internal to FitSession: what a run writes when it ends (best.json, summary.json, the best
// parameters' simulated logs and the plots) and the FitSummary it returns.

#include <cstdint>
#include <string>
#include <vector>

#include "fit_lm_polish.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex/fit/fit_summary.hpp"

namespace motoflex::detail {

struct RunResult {
  std::vector<double> best_x;  // empty: nothing was evaluated
  double best_fitness = 0.0;
  std::uint64_t generations = 0;
  std::uint64_t evaluations = 0;  // main strategy + polish
  std::uint64_t polish_evaluations = 0;
  std::string strategy;   // the main strategy's name
  std::string evaluator;  // the evaluator's name
  std::string stop_reason;
  bool converged = false;
  std::string convergence;
  double seconds = 0.0;
  // Per free coordinate: relative fitness change per bound-width (fit_sensitivity.hpp); empty
  // when not measured (an interrupted run).
  std::vector<double> sensitivity;
  // The least-squares finish and the uncertainty (`polish:`), when asked for.
  bool lm_ran = false;
  LmPolishResult lm;
  FitUncertainty uncertainty;
};

// Writes the outputs of a run into config.out_dir and returns its summary.
FitSummary write_fit_outputs(const FitConfig& config, const FitProblem& problem,
                             const RunResult& result);

}  // namespace motoflex::detail
