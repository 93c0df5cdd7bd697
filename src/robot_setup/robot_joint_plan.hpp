#pragma once

// Internal to init-robot: what becomes of each URDF joint in a new robot folder.

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/model/urdf_tree.hpp"
#include "motoflex/robot_setup/urdf_hints.hpp"

namespace motoflex::detail {

struct JointPlan {
  std::vector<std::string> actuated;  // the URDF's document order
  std::vector<std::pair<std::string, double>> held;
  std::vector<std::pair<std::string, std::string>> universal_pairs;
  std::vector<std::pair<std::string, std::pair<double, double>>> joint_limits;
  std::vector<std::pair<std::string, double>> stand_pose;  // only where 0 is outside the limits
  std::map<std::string, JointHints> hints;                 // per actuated joint
};

// Every movable joint is actuated except <mimic> followers (driven by their leader) and joints
// that move only massless links (held); a joint whose child is a massless link carrying the
// next joint, with axes crossing at right angles, forms a universal pair with it. Each choice
// that is not the plain default is added to `assumptions`.
JointPlan plan_joints(const UrdfTree& tree, std::vector<Assumption>& assumptions);

}  // namespace motoflex::detail
