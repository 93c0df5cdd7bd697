#pragma once

// What a fit runs on, written into its run dir as inputs.json so that later tools (the HTML
// report of `motoflex report`) can read a run dir without rebuilding the config from fit.yaml,
// which may have moved or changed since.

#include <nlohmann/json.hpp>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex {

// {"name", "fit", "scenario", "robot", "seed", "strategy": {...}, "budget": {...},
//  "effects": [...], "fitness": {"m", "settle_s", "window_s", "imu_weight"},
//  "free": [{"name", "unit", "start", "lower", "upper", "log", "targets": [...]}, ...],
//  "train_logs": [absolute paths], "validation_logs": [absolute paths]}.
// Values in model units (unit: the parameter name's suffix, "1" when dimensionless).
nlohmann::ordered_json fit_inputs_json(const FitConfig& config);

}  // namespace motoflex
