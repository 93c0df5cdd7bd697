#pragma once

#include <set>
#include <string>
#include <vector>

#include "motoflex/fit/parameter_space.hpp"
#include "motoflex/model/effect_library.hpp"
#include "motoflex/model/parameters.hpp"

namespace motoflex {

// One model parameter an effect sets, with its search range (search coordinates are log(value)
// for a log-scale parameter).
struct EffectTarget {
  std::string name;       // model parameter
  std::size_t parameter;  // index into Effect::parameters
  double lower = 0.0;
  double upper = 0.0;
  bool log_scale = false;
};

// The model parameters of `effect` for the registry of `base`, in effect-parameter order, then
// registry order. A pattern that matches nothing (e.g. gear parameters of a bench) is skipped.
std::vector<EffectTarget> effect_targets(const Effect& effect, const ParameterSet& base);

// The free parameters that switch `effect` on: one per target for `each` parameters, one tied
// value otherwise; targets listed in `taken` (already free or fixed) are left out. Start values
// are the base set's values, clamped into the bounds.
std::vector<FreeParameter> effect_free_parameters(const Effect& effect, const ParameterSet& base,
                                                  const std::set<std::string>& taken);

// Whether every target of `effect` is in `names` (e.g. the fit's free parameters: the effect is
// then already part of the model). False for an effect without targets.
bool effect_covered_by(const Effect& effect, const ParameterSet& base,
                       const std::set<std::string>& names);

}  // namespace motoflex
