#pragma once

#include <map>
#include <string>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex {

// The commanded angles of a joint log, or of a 2011 MoToFlex command file (recognised by its
// header, imported as motoflex/io/motoflex_command_file.hpp describes, original playback
// clock), in model actuator order (the log keeps its own column order). The log must be of
// `model`'s robot (when its sidecar says) and have a .cmd column per actuated joint; its sidecar's
// per-log parameters (e.g. a bench's mass) are applied to `parameters` and copied to
// `log_parameters`. `description` gets the sidecar's motion (or "replay of PATH"). Throws
// InputError naming the file and field.
CommandTrajectory read_log_commands(const RobotModel& model, const std::string& path,
                                    ParameterSet& parameters,
                                    std::map<std::string, double>& log_parameters,
                                    std::string* description = nullptr);

// The frames of `in` up to `duration_s` after its start.
CommandTrajectory truncate_trajectory(const CommandTrajectory& in, double duration_s);

}  // namespace motoflex
