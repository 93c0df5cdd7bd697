#pragma once

// Where a loop refit's search starts for the new effect's own parameters (LoopOptions::
// refit_scan). The signature regression's linearised estimate barely moves a parameter whose
// neutral value does nothing at all (a current limit far above any current: a zero slope), so
// the refit would search where the effect is switched off; a coarse scan across the bounds finds
// where it starts to act.

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/parameter_space.hpp"

namespace motoflex::detail {

// Each parameter of `estimate` that is free in `space` in turn, at `points` (>= 3) values evenly
// spaced across its bounds in search coordinates (log-spaced where `log_scale`), the others held;
// a value is kept only if `fitness` of the whole estimate falls below `best_fitness`, which is
// updated. Names not free in `space` are left alone.
void scan_effect_start(
    const ParameterSpace& space, std::size_t points,
    const std::function<double(const std::vector<std::pair<std::string, double>>&)>& fitness,
    std::vector<std::pair<std::string, double>>& estimate, double& best_fitness);

}  // namespace motoflex::detail
