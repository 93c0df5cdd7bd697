#pragma once

// `motoflex check-robot DIR`: every problem of a robot folder at once, or a short summary.

#include <string>
#include <vector>

#include "motoflex/core/error.hpp"

namespace motoflex {

struct RobotCheckReport {
  std::vector<InputError> problems;  // empty: the folder is fine
  std::vector<std::string> summary;  // describe_robot's lines and the held rollout's end
};

// Loads the folder (load_robot, collecting every problem of robot.yaml, the URDF, its meshes
// and the parameters) and, when it loads, holds its stand pose for `duration_s` with default
// parameters; a rollout that does not complete is a problem too.
RobotCheckReport check_robot_folder(const std::string& robot_dir, double duration_s = 1.0);

}  // namespace motoflex
