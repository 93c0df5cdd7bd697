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
//
// With `pairs_jointly` and exactly two coordinates listed, the whole points × points grid of the
// two instead (points² evaluations): a pair where one parameter switches the other on (winding
// heating's thermal resistance and heat capacity: with R_th = 0 the capacity does nothing, and at
// the neutral capacity no R_th heats within a log) has no coordinate-wise path to where both act.
// As in the coordinate-wise scan, the start is kept unless a grid point beats `best_fitness`, so
// the scan never makes it worse. The grid is not a superset of the coordinate-wise scan, which
// tries one parameter's values at the other's held value, not a grid point. Returns whether it
// scanned the pair's grid.
bool scan_effect_start(const ParameterSpace& space, const std::vector<std::size_t>& indices,
                       std::size_t points,
                       const std::function<double(const std::vector<double>&)>& fitness,
                       std::vector<double>& x, double& best_fitness, bool pairs_jointly = false);

}  // namespace motoflex::detail
