#pragma once

// Internal to FitSession: the LM polish and the parameter uncertainty as summary.json and the
// FitSummary report them.
//
//   "polish": {"method": "lm", "iterations", "evaluations", "fitness_before", "fitness_after",
//              "used", "termination"}
//   "confidence_intervals": {"<free parameter>": {"value", "standard_error", "lower", "upper",
//                            "share_of_bounds", "identified"}}   95 %, model units
//   "covariance" / "correlation": {"names": [...], "matrix": [[...]]}   model units
//   "uncertainty": {"method", "sigma2", "residuals", "parameters", "rank", "evaluations",
//                   "jacobian_step_share_of_bounds", "unidentified": [...],
//                   "covariance_search": {...}}   (search coordinates: log where log: true)
//
// These are the keys src/report (parameter_uncertainty.hpp) and src/export (provenance) read.

#include <nlohmann/json.hpp>

#include "fit_outputs.hpp"

namespace motoflex::detail {

// Fills the parameters' intervals and the summary's matrices from `result`, and adds the keys
// above to `json` (only those the run computed).
void add_uncertainty_outputs(const FitConfig& config, const RunResult& result, FitSummary& summary,
                             nlohmann::ordered_json& json);

}  // namespace motoflex::detail
