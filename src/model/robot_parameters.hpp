#pragma once

// Internal to the model loader: robot.yaml's `parameters:` section.

#include "motoflex/core/error_collector.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex::detail {

// Adds every `name: [default, lower, upper]` of robot.yaml's parameters to the model (with
// its line, for the checks of the sim layer), then the effects' parameters it does not
// declare, at their neutral values. Each bad entry goes to `errors`.
void read_robot_parameters(const YamlValue& root, RobotModel& model, ErrorCollector& errors);

}  // namespace motoflex::detail
