#include "motoflex/fit/effect_parameters.hpp"

#include <algorithm>
#include <cmath>

namespace motoflex {

std::vector<EffectTarget> effect_targets(const Effect& effect, const ParameterSet& base) {
  const ParameterRegistry& registry = base.registry();
  std::vector<EffectTarget> out;
  for (std::size_t p = 0; p < effect.parameters.size(); ++p) {
    const EffectParameter& parameter = effect.parameters[p];
    for (const std::string& name : match_parameter_pattern(registry, parameter.pattern)) {
      const ParameterSpec& spec = registry.spec(*registry.find(name));
      EffectTarget target;
      target.name = name;
      target.parameter = p;
      target.lower = std::isnan(parameter.lower) ? spec.lower : parameter.lower;
      target.upper = std::isnan(parameter.upper) ? spec.upper : parameter.upper;
      target.log_scale = parameter.log_scale && target.lower > 0.0;
      out.push_back(target);
    }
  }
  return out;
}

std::vector<FreeParameter> effect_free_parameters(const Effect& effect, const ParameterSet& base,
                                                  const std::set<std::string>& taken) {
  std::vector<FreeParameter> out;
  const std::vector<EffectTarget> targets = effect_targets(effect, base);
  for (std::size_t p = 0; p < effect.parameters.size(); ++p) {
    const EffectParameter& parameter = effect.parameters[p];
    FreeParameter tied;
    for (const EffectTarget& target : targets) {
      if (target.parameter != p || taken.count(target.name) > 0) continue;
      FreeParameter free;
      free.name = parameter.each ? target.name : parameter.pattern;
      free.targets = {target.name};
      free.lower = target.lower;
      free.upper = target.upper;
      free.log_scale = target.log_scale;
      free.start = std::clamp(base.get(target.name), target.lower, target.upper);
      if (parameter.each) {
        out.push_back(free);
      } else if (tied.targets.empty()) {
        tied = free;
      } else {
        tied.targets.push_back(target.name);
      }
    }
    if (!tied.targets.empty()) out.push_back(tied);
  }
  return out;
}

bool effect_covered_by(const Effect& effect, const ParameterSet& base,
                       const std::set<std::string>& names) {
  const std::vector<EffectTarget> targets = effect_targets(effect, base);
  if (targets.empty()) return false;
  return std::all_of(targets.begin(), targets.end(),
                     [&](const EffectTarget& t) { return names.count(t.name) > 0; });
}

}  // namespace motoflex
