#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace motoflex {

// Where one revolute joint of a serial leg is and which way it turns, in the world frame.
struct JointAxisFrame {
  Eigen::Vector3d point_m = Eigen::Vector3d::Zero();  // a point on the axis (the anchor)
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();    // unit; positive joint direction
};

// Translational Jacobian of a 3-joint serial leg at the point `tip_m` (world frame):
// column i = u_i × (r_tip − r_i), so that ṙ_tip = J θ̇ with the body held still.
Eigen::Matrix3d serial_leg_jacobian(const std::array<JointAxisFrame, 3>& joints,
                                    const Eigen::Vector3d& tip_m);

// Seed 000 eq. 7: τ_i = ((r_a − r_i) × F)·u_i — the static torque joint i needs to press the
// leg's point r_a with force F (the force the leg applies there, e.g. the force the ankle joint
// J4 transmits to the foot), leg masses neglected. Same sign as the actuator torque on the
// distal link: the joint must hold the moment −(r_a − r_i) × F_ext of the external force
// F_ext = −F acting on the leg.
double jacobian_joint_torque_nm(const JointAxisFrame& joint, const Eigen::Vector3d& force_point_m,
                                const Eigen::Vector3d& force_n);

// Eq. 6: τ_s = J_sᵀ F for all three joints (identical to eq. 7 row by row).
Eigen::Vector3d jacobian_leg_torques_nm(const std::array<JointAxisFrame, 3>& joints,
                                        const Eigen::Vector3d& force_point_m,
                                        const Eigen::Vector3d& force_n);

}  // namespace motoflex
