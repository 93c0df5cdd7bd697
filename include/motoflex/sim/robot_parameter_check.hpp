#pragma once

// The robot's declared parameters checked against what its rollouts read: the servo laws'
// names (servo_law.hpp) and the rollout-wide ones (contacts, world, sensors, flex, encoders).
// The model layer cannot do this itself, since the laws live here.

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// Loads a robot folder (load_robot_model) and checks it with check_robot_parameters: the one
// entry point for reading a robot. Throws InputError(s) naming robot.yaml's lines.
RobotModel load_robot(const std::string& robot_dir, const StructureOptions& structure);
// The same with every problem of both steps added to `errors` (a robot.yaml name the URDF does
// not have is reported once, not again as unknown parameters). Returns the model when the files
// could be read (check `errors` before using it), nullopt otherwise.
std::optional<RobotModel> load_robot(const std::string& robot_dir,
                                     const StructureOptions& structure, ErrorCollector& errors);

// Every parameter name a rollout of `model` with servo law `servo` reads, in a stable order
// (`servo` empty: each joint's own law, actuator_servo_name). Throws std::invalid_argument for
// an unknown law.
std::vector<std::string> rollout_parameter_names(const RobotModel& model, const std::string& servo);

// Every name a robot.yaml of this model may declare: what any law or the rollout may read.
std::set<std::string> known_parameter_names(const RobotModel& model);

// Checks every declared name is known (with a "did you mean"), robot.yaml's servo is a
// registered law, and every name that law reads is declared. Reports all problems at once
// (InputErrors), each at its robot.yaml line.
void check_robot_parameters(const RobotModel& model);
// The same into `errors`; `report_unknown` false skips the "unknown parameter" check.
void check_robot_parameters(const RobotModel& model, ErrorCollector& errors, bool report_unknown);

// Checks that `servo` is a registered law and the robot declares every name it reads; problems
// are reported at `source`:`line`: `field` (e.g. a scenario's `servo:` key).
void check_servo_parameters(const RobotModel& model, const std::string& servo,
                            const std::string& source, int line, const std::string& field);

}  // namespace motoflex
