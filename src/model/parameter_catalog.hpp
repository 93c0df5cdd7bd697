#pragma once

// Internal to the model loader: which parameter names exist for a robot and which ones each
// servo kind reads. The list of names a robot.yaml may declare lives here and nowhere else.

#include <set>
#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

// Every name a robot.yaml may declare for this model (any servo kind).
std::set<std::string> known_parameter_names(const RobotModel& model);

// Parameters of the model effects (encoder offset and scale, Stribeck and load-dependent
// friction, motor-resistance drift, supply sag, sensor realism) with neutral defaults: with
// these values an effect is absent. The loader adds every one a robot.yaml does not declare,
// so any robot can switch an effect on by giving its parameters a value.
std::vector<ParameterSpec> effect_parameter_specs(const RobotModel& model);

// The names a servo kind reads (plus the flex, contact, world and sensor names every rollout
// reads), in a stable order.
std::vector<std::string> required_parameter_names(const RobotModel& model, ServoKind servo);

}  // namespace motoflex::detail
