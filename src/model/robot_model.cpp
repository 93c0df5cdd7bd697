#include "motoflex/model/robot_model.hpp"

namespace motoflex {

const char* to_string(ShapeKind kind) {
  switch (kind) {
    case ShapeKind::kBox:
      return "box";
    case ShapeKind::kSphere:
      return "sphere";
    case ShapeKind::kCylinder:
      return "cylinder";
    case ShapeKind::kCapsule:
      return "capsule";
    case ShapeKind::kMesh:
      return "mesh";
  }
  return "?";
}

std::optional<std::size_t> RobotModel::actuator_index(const std::string& joint_name) const {
  for (std::size_t i = 0; i < actuators.size(); ++i) {
    if (actuators[i].name == joint_name) return i;
  }
  return std::nullopt;
}

std::vector<std::string> RobotModel::actuator_names() const {
  std::vector<std::string> names;
  names.reserve(actuators.size());
  for (const auto& a : actuators) names.push_back(a.name);
  return names;
}

std::vector<double> RobotModel::stand_pose_vector() const {
  std::vector<double> pose(actuators.size(), 0.0);
  for (std::size_t i = 0; i < actuators.size(); ++i) {
    const auto it = stand_pose_rad.find(actuators[i].name);
    if (it != stand_pose_rad.end()) pose[i] = it->second;
  }
  return pose;
}

}  // namespace motoflex
