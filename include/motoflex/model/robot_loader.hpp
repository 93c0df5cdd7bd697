#pragma once

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// Loads `<robot_dir>/robot.yaml` and the URDF it names into an immutable RobotModel: links
// welded by fixed or held joints become one body, declared hinge pairs become universal joints
// (if enabled), flexible links are split into sub-bodies. Throws InputError naming file, line
// and field for any problem with either file.
RobotModel load_robot_model(const std::string& robot_dir, const StructureOptions& structure);

// Names of the parameters a servo kind reads for this model, in a stable order.
std::vector<std::string> required_parameters(const RobotModel& model, ServoKind servo);

}  // namespace motoflex
