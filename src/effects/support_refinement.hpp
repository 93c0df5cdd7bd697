#pragma once

// Internal to src/effects/: the nonlinear check of a discovered support. The sparse regression
// of term_discovery.cpp is linearised at the fit's point, and where the missing torque has been
// half absorbed by the fit's own parameters (quadratic drag by a larger viscous and a smaller
// Coulomb term, whose stick–slip response is far from linear) the linearised coefficient can be
// an order of magnitude off. refine_support runs a few Levenberg–Marquardt iterations on
// rollouts — the support's coefficients and the fit's free parameters together, a fresh
// finite-difference Jacobian each iteration, a step accepted only if the training fitness falls
// — so supports are compared by what they do, not by their first-order estimate.

#include <cstddef>
#include <string>
#include <vector>

#include "linearised_residual.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex::detail {

// One coordinate of the refinement: a model parameter (a term's coefficient, in model units)
// or a free parameter of the fit (in its search coordinate, written to all its targets).
struct RefinedCoordinate {
  std::vector<std::string> targets;
  std::size_t free_index = 0;  // the fit's free parameter; unused for a term
  bool term = false;
  double value = 0.0, step = 0.0, lower = 0.0, upper = 0.0;
};

struct RefinedSupport {
  std::vector<double> values;  // per coordinate, at the best point found
  double fitness = 0.0;        // training fitness there
  std::size_t rollouts = 0;    // passes over all training logs
  int accepted_steps = 0;
};

// `start` holds the coordinates' starting values (and the start's training fitness in
// `start_fitness`); `current` supplies every other parameter. Serial (the caller runs supports
// in parallel); deterministic.
RefinedSupport refine_support(const FitConfig& config, const ParameterSet& current,
                              const std::vector<RefinedCoordinate>& start, double start_fitness,
                              int iterations);

}  // namespace motoflex::detail
