#pragma once

// Looking at a robot as `motoflex init-robot` and `check-robot` do: which links it stands on,
// whether it simulates, and a short description.

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"
#include "motoflex/model/urdf_tree.hpp"
#include "motoflex/robot_setup/urdf_hints.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// Leaf links with collision geometry (no link below them has any), with the lowest point of
// their shapes when `model` stands in `pose` (its actuator order) with the base unmoved.
struct LinkHeight {
  std::string link;
  double lowest_z_m = 0.0;
};
std::vector<LinkHeight> leaf_link_heights(const UrdfTree& tree, const RobotModel& model,
                                          const std::vector<double>& pose);

// The leaf links within max(5 mm, 2 % of the robot's height) of the lowest of them: what a
// floating-base robot stands on in `pose`. With `at_robot_bottom`, only when that lowest leaf
// is also the robot's lowest point (so a mounted arm's fingers do not count).
std::vector<std::string> lowest_leaf_links(const UrdfTree& tree, const RobotModel& model,
                                           const std::vector<double>& pose,
                                           bool at_robot_bottom = false);

// Holds the stand pose for `duration_s` with every parameter at its default, each joint under
// its own law, a floating base held in the air (0.1 m above the ground): does the robot
// simulate at all?
RolloutResult hold_stand_pose(const RobotModel& model, double duration_s);

// One line per fact: bodies, joints by kind, actuators by law, total mass, collision shapes by
// kind, feet, visual meshes not found.
std::vector<std::string> describe_robot(const RobotModel& model);

}  // namespace motoflex
