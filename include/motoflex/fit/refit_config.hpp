#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex {

// Writes `<dir>/fit.yaml`, the warm-started refit of `from` with `effect` added, and returns
// its path. Every free parameter of `from` starts at its fitted value (`fitted_free`: free
// parameter name → value, as in best.json's "free"); the effect's new parameters start at
// `effect_start` (model parameter → value, e.g. the signature regression's estimate); strategy
// and budget are from.loop's refit options; the logs are from's, by absolute path. The file is
// a plain fit config (JSON, which YAML reads), so `motoflex fit`, `resume` and `residuals`
// work on it as on any other.
FitSpec refit_spec(const FitConfig& from, const nlohmann::json& fitted_free, const Effect& effect,
                   const std::vector<std::pair<std::string, double>>& effect_start,
                   const std::string& dir);
// refit_spec written as `<dir>/fit.yaml`; returns its path.
std::string write_refit_config(const FitConfig& from, const nlohmann::json& fitted_free,
                               const Effect& effect,
                               const std::vector<std::pair<std::string, double>>& effect_start,
                               const std::string& dir);

}  // namespace motoflex
