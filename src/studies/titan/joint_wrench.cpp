#include "motoflex/studies/titan/joint_wrench.hpp"
#include <Eigen/Geometry>

namespace motoflex {

JointWrench joint_wrench_at_point(const Eigen::Vector3d& force_n, const Eigen::Vector3d& torque_nm,
                                  const Eigen::Vector3d& body_com_m,
                                  const Eigen::Vector3d& joint_point_m) {
  // Seed 000 eq. 4: t + (P_body − P_j) × f.
  return {force_n, torque_nm + (body_com_m - joint_point_m).cross(force_n)};
}

JointWrench joint_load(const JointWrench& on_body1) {
  return {-on_body1.force_n, -on_body1.moment_nm};
}

JointWrench third_law_residual(const JointWrench& on_body1, const JointWrench& on_body2) {
  return {on_body1.force_n + on_body2.force_n, on_body1.moment_nm + on_body2.moment_nm};
}

double joint_axis_torque_nm(const JointWrench& on_body1, const Eigen::Vector3d& axis) {
  return on_body1.moment_nm.dot(axis);
}

}  // namespace motoflex
