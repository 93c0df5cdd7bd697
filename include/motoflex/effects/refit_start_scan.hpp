#pragma once

// Where a loop refit's search starts for the new effect's own parameters (LoopOptions::
// refit_scan). The signature regression's linearised estimate barely moves a parameter whose
// neutral value does nothing at all (a current limit far above any current: a zero slope), so
// the refit would search where the effect is switched off; a coarse scan across the bounds finds
// where it starts to act.

#include <cstddef>
#include <functional>
#include <vector>

#include "motoflex/fit/parameter_space.hpp"

namespace motoflex::detail {

// Each coordinate of `x` listed in `indices` in turn, at `points` (>= 3) values evenly spaced
// between the space's search bounds (so log-spaced where `log_scale`), the others held; a value
// is kept only if `fitness(x)` falls below `best_fitness`, which is updated. Coordinates not
// listed are left alone.
void scan_effect_start(const ParameterSpace& space, const std::vector<std::size_t>& indices,
                       std::size_t points,
                       const std::function<double(const std::vector<double>&)>& fitness,
                       std::vector<double>& x, double& best_fitness);

}  // namespace motoflex::detail
