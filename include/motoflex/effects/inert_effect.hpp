#pragma once

// Whether a loop refit's new effect helps at the refit's optimum (effect_loop.hpp,
// LoopRefit::inert). A refit frees the current model's parameters and the effect's; a wide
// search can end at a better optimum of the model's own parameters where the effect does
// nothing (a Stribeck term fitted to 0 N·m, a current limit above every current the logs draw)
// or even harms (a budget-limited search that left the effect on where switching it off scores
// better). Such a refit only re-optimised the model, and its gain must not go to the effect.

#include <cstddef>

#include "motoflex/fit/fitness.hpp"
#include "motoflex/fit/parameter_space.hpp"
#include "motoflex/model/parameters.hpp"

namespace motoflex {

// True when `refit_best` with the effect's parameters (the free parameters of `refit_space` from
// index `model_parameters` on, i.e. after the current model's own) set to their values in
// `current` scores no worse on `train` than `refit_best` itself. Two passes over the logs.
bool effect_is_inert(const FitnessFunction& train, const ParameterSpace& refit_space,
                     std::size_t model_parameters, const ParameterSet& refit_best,
                     const ParameterSet& current);

}  // namespace motoflex
