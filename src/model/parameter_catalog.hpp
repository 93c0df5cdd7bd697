#pragma once

// Internal to the model loader: the model effects' parameters, which every robot has (with
// neutral defaults unless robot.yaml declares them). The names each servo law reads are the
// law's own (src/sim/actuator/), checked by the sim layer.

#include <set>
#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

// Parameters of the model effects (encoder offset and scale, Stribeck and load-dependent
// friction, motor-resistance drift, supply sag, sensor realism) with neutral defaults: with
// these values an effect is absent. The loader adds every one a robot.yaml does not declare,
// so any robot can switch an effect on by giving its parameters a value.
std::vector<ParameterSpec> effect_parameter_specs(const RobotModel& model);

}  // namespace motoflex::detail
