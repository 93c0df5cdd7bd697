#include "motoflex/sim/effect_hooks.hpp"

#include <algorithm>
#include <vector>

#include "motoflex/sim/robot_parameter_check.hpp"

namespace motoflex {

bool effect_applies(const Effect& effect, const RobotModel& model, const std::string& servo) {
  if (effect.needs_feet) {
    bool has_feet = false;
    for (const auto& body : model.bodies) {
      for (const auto& shape : body.collisions) has_feet = has_feet || shape.is_foot;
    }
    if (!has_feet) return false;
  }
  if (effect.flex_sub_bodies >= 2) return true;
  const std::vector<std::string> read = rollout_parameter_names(model, servo);
  for (const EffectParameter& parameter : effect.parameters) {
    const bool hooked = std::any_of(read.begin(), read.end(), [&](const std::string& name) {
      return parameter_pattern_matches(parameter.pattern, name);
    });
    if (!hooked) return false;
  }
  return true;
}

}  // namespace motoflex
