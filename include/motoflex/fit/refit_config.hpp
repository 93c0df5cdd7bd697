#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex {

// The refit of `from` with `effect` added, as a fit spec whose run folder is `dir`. The current
// model, `fitted_free` (free parameter name → value, as in best.json's "free"), is the refit's
// `incumbent` with the effect at its neutral value: evaluated before the search, so a refit never
// ends with a worse training fitness than the model it extends. The search starts at
// `start_free` (default: `fitted_free`; the loop may move the fit's own parameters to the
// signature regression's linearised optimum) with the effect's new parameters at
// `effect_start` (model parameter → value, e.g. the regression's estimate). Strategy and budget
// are from.loop's refit options; the logs are from's, by absolute path. With
// `start_is_incumbent` (the loop found a start better than the current model) the start is the
// incumbent instead: a search that samples only around its start never drops below it.
FitSpec refit_spec(const FitConfig& from, const nlohmann::json& fitted_free, const Effect& effect,
                   const std::vector<std::pair<std::string, double>>& effect_start,
                   const std::string& dir, const nlohmann::json& start_free = nullptr,
                   bool start_is_incumbent = false);
// refit_spec written as `<dir>/fit.yaml` (a plain fit config, JSON, which YAML reads, so
// `motoflex fit`, `resume` and `residuals` work on it as on any other); returns its path.
std::string write_refit_config(const FitConfig& from, const nlohmann::json& fitted_free,
                               const Effect& effect,
                               const std::vector<std::pair<std::string, double>>& effect_start,
                               const std::string& dir, const nlohmann::json& start_free = nullptr,
                               bool start_is_incumbent = false);

// The model of `from`, nothing added, at `fitted_free`'s values of its own free parameters (other
// names in it are ignored), as a fit spec in `dir` whose search is a single evaluation of those
// values (they are its start and incumbent; budget one evaluation, no polish, no covariance): how
// the loop carries a refit's re-optimised values over to the model without the refit's effect.
FitSpec evaluation_spec(const FitConfig& from, const nlohmann::json& fitted_free,
                        const std::string& dir);

}  // namespace motoflex
