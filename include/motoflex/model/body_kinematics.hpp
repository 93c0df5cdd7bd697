#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// World pose of every body frame (origin at the body's CoM) for the given actuated joint
// angles (model actuator order; flex joints straight), with the root body at its
// build-configuration pose.
std::vector<Eigen::Isometry3d> body_poses(const RobotModel& model,
                                          const std::vector<double>& actuator_angles_rad);

// Lowest z over all corners of the foot boxes (+inf when the robot has no feet).
double lowest_foot_point_z(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses);

}  // namespace motoflex
