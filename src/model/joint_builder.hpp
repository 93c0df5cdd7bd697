#pragma once

// Internal to the model loader: the ODE joints between the lumped bodies and the actuators.

#include <Eigen/Geometry>
#include <vector>

#include "link_lumping.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/model/urdf_tree.hpp"
#include "robot_yaml.hpp"

namespace motoflex::detail {

// Adds to `model` (whose bodies are built) one joint per movable URDF joint that is neither
// held nor the second axis of a merged universal pair, in the bodies' breadth-first order:
// hinges (revolute, continuous), sliders (prismatic), universal and flex joints, with the URDF
// limits as stops unless robot.yaml says joint_stops: false; then the actuators in robot.yaml
// order with their servo law and scope (`servos:`), and the <mimic> couplings. Problems go to
// `errors`.
void build_joints(RobotModel& model, const UrdfTree& tree, const Lumping& lumping,
                  const std::vector<Eigen::Isometry3d>& X_WL, const RobotYaml& spec,
                  ErrorCollector& errors);

}  // namespace motoflex::detail
