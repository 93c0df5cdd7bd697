#pragma once

// A finished fit as later steps use it: its config (rebuilt from run.json exactly as `motoflex
// resume` does), its best parameter set and its errors on the training and validation logs.

#include <nlohmann/json.hpp>
#include <string>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_report.hpp"

namespace motoflex {

struct FinishedFit {
  FitConfig config;
  ParameterSet best;
  nlohmann::json best_json;  // best.json ("free": name → value, "parameters", ...)
  nlohmann::json summary;    // summary.json
};

// Throws InputError naming the run dir when it holds no finished fit (no run.json, no
// summary.json, or a fit that was interrupted: resume it first).
FinishedFit load_finished_fit(const std::string& run_dir);

// Runs the fit of `config` into config.out_dir unless a finished one is there already: a fit
// cut short (killed or interrupted) is resumed from its checkpoint, so a killed loop loses at
// most the generation in flight. Returns the finished fit.
FinishedFit ensure_fit(const FitConfig& config);

// Error statistics of a parameter set on one list of logs (model units: rad).
struct ErrorSummary {
  double rms_deg = 0.0;     // joint encoders
  double mae_rad = 0.0;     // joint encoders: mean absolute error over the scored frames (BAM's)
  std::size_t samples = 0;  // scored frames × the fitness's channels
  // Over the fitness's channels (joints with their weights, and the IMU when it is scored):
  double channel_rms_rad = 0.0;  // √(MSE)
  // The error as the fit measures it: √(MSE) for squared errors, the mean w·|e| for absolute
  // ones (FitnessOptions::absolute_error), so that the loop judges a refit by its own loss.
  double fit_error_rad = 0.0;
  // 2·samples·ln(fit_error) + free·ln(samples): Gaussian errors' BIC for squared errors,
  // Laplace errors' for absolute ones (up to constants that cancel between two models).
  double bic = 0.0;
  DetailedEvaluation detail;
};
ErrorSummary summarize_errors(const FitnessFunction& fitness, const ParameterSet& set,
                              std::size_t free_parameters);
// RMS of the torso IMU's roll and pitch errors together (deg); NaN without IMU columns.
double imu_rms_deg(const ErrorSummary& errors);

}  // namespace motoflex
