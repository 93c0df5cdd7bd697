#include "motoflex/studies/titan/leg_jacobian_torque.hpp"
#include <Eigen/Geometry>

namespace motoflex {

Eigen::Matrix3d serial_leg_jacobian(const std::array<JointAxisFrame, 3>& joints,
                                    const Eigen::Vector3d& tip_m) {
  Eigen::Matrix3d J;
  for (int i = 0; i < 3; ++i) J.col(i) = joints[i].axis.cross(tip_m - joints[i].point_m);
  return J;
}

double jacobian_joint_torque_nm(const JointAxisFrame& joint, const Eigen::Vector3d& force_point_m,
                                const Eigen::Vector3d& force_n) {
  // Seed 000 eq. 7.
  return (force_point_m - joint.point_m).cross(force_n).dot(joint.axis);
}

Eigen::Vector3d jacobian_leg_torques_nm(const std::array<JointAxisFrame, 3>& joints,
                                        const Eigen::Vector3d& force_point_m,
                                        const Eigen::Vector3d& force_n) {
  // Seed 000 eq. 6; (u × d)·F = (d × F)·u, so each row is eq. 7.
  return serial_leg_jacobian(joints, force_point_m).transpose() * force_n;
}

}  // namespace motoflex
