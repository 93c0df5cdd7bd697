#pragma once

#include <string>

#include "motoflex/model/effect_library.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// Whether a rollout of `model` with servo law `servo` has the effect's hook: every parameter
// pattern of the effect matches a name the law or the rollout reads (a law that has no joint
// friction cannot show Coulomb friction), and a ground effect needs feet. An effect that needs
// sub-bodies (flex_sub_bodies >= 2) is hooked by the structure the caller builds for it.
bool effect_applies(const Effect& effect, const RobotModel& model, const std::string& servo);

}  // namespace motoflex
