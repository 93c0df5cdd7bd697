#include "motoflex/model/body_kinematics.hpp"

#include <algorithm>
#include <limits>

namespace motoflex {

std::vector<Eigen::Isometry3d> body_poses(const RobotModel& model,
                                          const std::vector<double>& actuator_angles_rad) {
  std::vector<Eigen::Isometry3d> poses(model.bodies.size(), Eigen::Isometry3d::Identity());
  poses[model.root_body].translation() = model.bodies[model.root_body].com_W0_m;
  // Joints are stored parents-first; every body frame has world orientation at build config,
  // so a joint's axes and anchor, read in the parent frame, are its build-config world values.
  for (const JointSpec& joint : model.joints) {
    const BodySpec& parent = model.bodies[joint.parent_body];
    const BodySpec& child = model.bodies[joint.child_body];
    const double q1 = joint.actuator1 >= 0 ? actuator_angles_rad.at(joint.actuator1) : 0.0;
    const double q2 = joint.actuator2 >= 0 ? actuator_angles_rad.at(joint.actuator2) : 0.0;
    const Eigen::Vector3d anchor_P = joint.anchor_W0_m - parent.com_W0_m;
    Eigen::Matrix3d R = Eigen::AngleAxisd(q1, joint.axis1_W0).toRotationMatrix();
    if (joint.kind != JointKind::kHinge) R = R * Eigen::AngleAxisd(q2, joint.axis2_W0);
    Eigen::Isometry3d X_PC = Eigen::Isometry3d::Identity();
    X_PC.linear() = R;
    X_PC.translation() = anchor_P + R * (child.com_W0_m - joint.anchor_W0_m);
    poses[joint.child_body] = poses[joint.parent_body] * X_PC;
  }
  return poses;
}

double lowest_foot_point_z(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const BoxGeom& box : model.bodies[b].boxes) {
      if (!box.is_foot) continue;
      const Eigen::Isometry3d X_WG = poses[b] * box.X_BG;
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d local(((corner & 1) ? 0.5 : -0.5) * box.size_m.x(),
                                    ((corner & 2) ? 0.5 : -0.5) * box.size_m.y(),
                                    ((corner & 4) ? 0.5 : -0.5) * box.size_m.z());
        lowest = std::min(lowest, (X_WG * local).z());
      }
    }
  }
  return lowest;
}

}  // namespace motoflex
