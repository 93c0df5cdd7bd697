#pragma once

// Internal to the model loader: robot.yaml's names checked against the URDF.

#include "motoflex/core/error_collector.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/urdf_tree.hpp"
#include "robot_yaml.hpp"

namespace motoflex::detail {

// Checks every joint and link robot.yaml names (actuated, held, universal pairs, servos,
// stand pose, flexible links, feet, contact/trimesh/capsule links, base and torso) against
// the URDF. Each problem goes to `errors` (at its robot.yaml line) and its entry is dropped,
// so the model can still be built from the rest. Fills in the defaults that need the URDF
// (root and torso link) and holds the mimic followers of held joints.
void check_robot_yaml(RobotYaml& spec, const UrdfTree& tree, const YamlValue& root,
                      ErrorCollector& errors);

}  // namespace motoflex::detail
