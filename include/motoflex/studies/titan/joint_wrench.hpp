#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace motoflex {

// The force and moment a joint exerts on one of its bodies, reduced to the joint point.
struct JointWrench {
  Eigen::Vector3d force_n = Eigen::Vector3d::Zero();    // world frame
  Eigen::Vector3d moment_nm = Eigen::Vector3d::Zero();  // about the joint point, world frame
};

// Seed 000 eq. 4–5: ODE's dJointGetFeedback reports the force f and torque t a joint applies to
// a body *at that body's centre of mass* (world frame, ode_and_titan8.md §2.1). Moving the
// reference point to the joint point P_j adds the moment of f:
//   moment about P_j = t + (P_body − P_j) × f.
// `force_n`, `torque_nm` are f1/t1 (or f2/t2), `body_com_m` is P1 (or P2), `joint_point_m` P_j.
JointWrench joint_wrench_at_point(const Eigen::Vector3d& force_n, const Eigen::Vector3d& torque_nm,
                                  const Eigen::Vector3d& body_com_m,
                                  const Eigen::Vector3d& joint_point_m);

// The load a joint carries in the paper's sign: the left side of eq. 4 with the sign inverted,
// i.e. the wrench body 1 exerts on the joint (−what the joint exerts on body 1). For the knee of
// a standing leg (body 1 = shank) the vertical component is the weight carried above the knee.
JointWrench joint_load(const JointWrench& on_body1);

// Eq. 4 residual: what the joint exerts on body 1 plus what it exerts on body 2, both about the
// same joint point. Newton's third law makes it zero for a joint that stores no momentum.
JointWrench third_law_residual(const JointWrench& on_body1, const JointWrench& on_body2);

// Eq. 5 projected on the joint axis: the torque the joint applies to body 1 about `axis` (unit,
// world frame). For a hinge whose body 1 is the child and whose axis is the joint's positive
// direction this is the actuator torque, positive when it drives the joint angle up.
double joint_axis_torque_nm(const JointWrench& on_body1, const Eigen::Vector3d& axis);

}  // namespace motoflex
