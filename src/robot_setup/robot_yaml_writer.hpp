#pragma once

// Internal to robot_setup: a robot folder's robot.yaml as text (format:
// scenarios/robots/README.md).

#include <string>
#include <utility>
#include <vector>

#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex::detail {

struct RobotFolderSpec {
  std::string header;  // comment lines at the top (without '#')
  std::string name;
  std::string urdf;  // as robot.yaml should say it (relative to the folder, or absolute)
  std::string base_link;
  bool fixed_base = false;
  bool ground = true;
  std::string servo;
  std::vector<std::pair<std::string, std::string>> servos;  // joint → law, where not `servo`
  std::vector<std::string> actuated;                        // log column order; each its own group
  std::vector<std::pair<std::string, double>> held;
  std::vector<std::pair<std::string, std::string>> universal_pairs;
  std::vector<std::string> feet;
  std::vector<std::pair<std::string, std::pair<double, double>>> joint_limits;
  std::vector<std::pair<std::string, double>> stand_pose;
  std::vector<ParameterDefault> parameters;
};

std::string robot_yaml_text(const RobotFolderSpec& spec);

}  // namespace motoflex::detail
