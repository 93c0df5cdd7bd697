#pragma once

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// Loads `<robot_dir>/robot.yaml` and the URDF it names into an immutable RobotModel: links
// welded by fixed or held joints become one body, declared hinge pairs become universal joints
// (if enabled), flexible links are split into sub-bodies. Throws InputError naming file, line
// and field for any problem with either file. The parameter names are checked against the servo
// laws one layer up (load_robot in motoflex/sim/robot_parameter_check.hpp); call that one.
RobotModel load_robot_model(const std::string& robot_dir, const StructureOptions& structure);

}  // namespace motoflex
