#pragma once

// Internal to resolve_fit_config: `hold_identified: true` with `--start-from RUN/best.json`.
// A chained fit searches only what the earlier run could not determine: the free parameters
// RUN's summary.json marks identified (its 95 % interval narrow and the residual linear across
// it, polish covariance) are held at their best.json values, the others stay free.

#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/parameter_space.hpp"

namespace motoflex::detail {

// A held free parameter: its name (as in the fit config) and the value every target takes.
struct HeldParameter {
  std::string name;
  std::vector<std::string> targets;
  double value = 0.0;
};

// Reads `summary_json` (the summary.json beside the --start-from best.json) and moves out of
// `free` (and out of `incumbent`, the start point by free parameter name) every parameter whose
// confidence_intervals entry has "identified": true or that the earlier run itself held (its
// "held_identified", so a chain's third stage holds what its first identified); returns them with
// their start (the best.json value). Throws InputError naming the file when the summary is
// missing, unreadable or has neither (the first run needs `polish: {covariance: true}`), or when
// nothing would be left to search.
std::vector<HeldParameter> hold_identified(const std::string& summary_json,
                                           std::vector<FreeParameter>& free,
                                           std::vector<std::pair<std::string, double>>& incumbent);

}  // namespace motoflex::detail
