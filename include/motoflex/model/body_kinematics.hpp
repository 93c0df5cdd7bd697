#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// World pose of every body frame (origin at the body's CoM) for the given actuated joint
// positions (model actuator order, rad or m; flex joints straight, mimic followers at
// multiplier·leader + offset), with the root body at its build-configuration pose.
std::vector<Eigen::Isometry3d> body_poses(const RobotModel& model,
                                          const std::vector<double>& actuator_positions);

// Lowest world z of one collision shape whose body frame is at X_WB: box corners, sphere,
// cylinder rim, capsule cap, the vertices of a hull or trimesh. A mesh shape without its hull
// or triangles counts as +inf.
double lowest_point_z(const CollisionShape& shape, const Eigen::Isometry3d& X_WB);

// Lowest z over all foot shapes (+inf when the robot has no feet).
double lowest_foot_point_z(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses);

// Lowest z over every collision shape (+inf when the robot has none).
double lowest_shape_point_z(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses);

}  // namespace motoflex
