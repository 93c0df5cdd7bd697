#pragma once

// The residual ranking of a fit that did not converge mixes the missing effects with the
// optimiser's unfinished work: a joint still far from its optimum leaves a residual that some
// effect's signature happens to match, a false "missing effect". `motoflex residuals` and
// `motoflex loop` therefore refuse such a fit unless forced, and then mark every ranking
// unreliable.

#include <string>

#include "motoflex/fit/fit_run.hpp"

namespace motoflex {

// "" when `fit`'s summary.json says it converged (or predates the `converged` field); else why
// not, e.g. "the fit did not converge (not converged: budget (max_evaluations))". With
// force = false an unconverged fit throws InputError (summary.json, field `converged`) whose
// message says how to go on; `command` names the refusing command in it.
std::string check_converged_for_ranking(const FinishedFit& fit, const std::string& run_dir,
                                        bool force, const std::string& command);

}  // namespace motoflex
