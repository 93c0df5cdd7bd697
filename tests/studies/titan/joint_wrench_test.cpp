// Seed 000 eq. 4–5: moving ODE's joint feedback from a body's CoM to the joint point, checked
// against hand-computed cases and against ODE 0.16 itself (a horizontal rod held by a hinge
// motor, whose CoM torque is zero while its joint torque is −m g L/2).

#include <gtest/gtest.h>
#include <ode/ode.h>

#include <cmath>

#include "motoflex/sim/ode_runtime.hpp"
#include "motoflex/studies/titan/joint_wrench.hpp"
#include "motoflex/studies/titan/leg_jacobian_torque.hpp"

namespace motoflex {
namespace {

TEST(JointWrench, MovesTheFeedbackToTheJointPointByHand) {
  // d = P1 − Pj = (0.1, −0.05, −0.3); d × f = (−0.75, −0.6, −0.15); plus t = (−0.25, −0.6, −0.55).
  const JointWrench w =
      joint_wrench_at_point({1.0, -2.0, 3.0}, {0.5, 0.0, -0.4}, {0.1, 0.2, -0.3}, {0.0, 0.25, 0.0});
  EXPECT_NEAR(w.moment_nm.x(), -0.25, 1e-12);
  EXPECT_NEAR(w.moment_nm.y(), -0.6, 1e-12);
  EXPECT_NEAR(w.moment_nm.z(), -0.55, 1e-12);
  EXPECT_EQ(w.force_n, Eigen::Vector3d(1.0, -2.0, 3.0));
  EXPECT_NEAR(joint_axis_torque_nm(w, Eigen::Vector3d::UnitX()), -0.25, 1e-12);
  const JointWrench load = joint_load(w);
  EXPECT_EQ(load.force_n, Eigen::Vector3d(-1.0, 2.0, -3.0));
  EXPECT_NEAR(load.moment_nm.y(), 0.6, 1e-12);
}

TEST(JointWrench, StaticRodByHand) {
  // A rod of mass m, length L along +x, hinged at the origin about +y and held still. The joint
  // pushes up with m g at the hinge and holds the gravity moment: about the CoM the two cancel
  // (t1 = 0), about the joint the torque is −m g L/2 (the paper's point: t1 is not the joint
  // torque).
  const double m = 2.0, g = 9.81, L = 0.4;
  const Eigen::Vector3d f1(0.0, 0.0, m * g), t1 = Eigen::Vector3d::Zero();
  const JointWrench w = joint_wrench_at_point(f1, t1, {L / 2, 0.0, 0.0}, Eigen::Vector3d::Zero());
  EXPECT_NEAR(joint_axis_torque_nm(w, Eigen::Vector3d::UnitY()), -m * g * L / 2, 1e-12);
  // Eq. 4: the other side of the joint (the world, "body 2" at any point) sees the opposite.
  const JointWrench on_body2 = joint_wrench_at_point(
      -f1, {0.0, m * g * L / 2, 0.0}, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  const JointWrench residual = third_law_residual(w, on_body2);
  EXPECT_NEAR(residual.force_n.norm(), 0.0, 1e-12);
  EXPECT_NEAR(residual.moment_nm.norm(), 0.0, 1e-12);
}

TEST(JointWrench, OdeFeedbackOfAHeldRodGivesTheHandResult) {
  ensure_ode_ready();
  const double m = 2.0, L = 0.4, g = 9.81;
  dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0.0, 0.0, -g);
  dBodyID rod = dBodyCreate(world);
  dMass mass;
  dMassSetBoxTotal(&mass, m, L, 0.02, 0.02);
  dBodySetMass(rod, &mass);
  dBodySetPosition(rod, L / 2, 0.0, 1.0);
  dJointID hinge = dJointCreateHinge(world, nullptr);
  dJointAttach(hinge, rod, nullptr);  // body 1 = rod, body 2 = the static world
  dJointSetHingeAnchor(hinge, 0.0, 0.0, 1.0);
  dJointSetHingeAxis(hinge, 0.0, 1.0, 0.0);
  dJointSetHingeParam(hinge, dParamVel, 0.0);  // velocity servo holding the rod still
  dJointSetHingeParam(hinge, dParamFMax, 100.0);
  dJointFeedback feedback;
  dJointSetFeedback(hinge, &feedback);
  for (int k = 0; k < 10; ++k) dWorldStep(world, 0.001);
  const Eigen::Vector3d f1(feedback.f1[0], feedback.f1[1], feedback.f1[2]);
  const Eigen::Vector3d t1(feedback.t1[0], feedback.t1[1], feedback.t1[2]);
  const dReal* p = dBodyGetPosition(rod);
  dVector3 anchor;
  dJointGetHingeAnchor(hinge, anchor);
  const JointWrench w =
      joint_wrench_at_point(f1, t1, {p[0], p[1], p[2]}, {anchor[0], anchor[1], anchor[2]});
  EXPECT_NEAR(f1.z(), m * g, 1e-6);
  EXPECT_NEAR(t1.norm(), 0.0, 1e-6);  // about the CoM: nothing
  EXPECT_NEAR(joint_axis_torque_nm(w, Eigen::Vector3d::UnitY()), -m * g * L / 2, 1e-6);
  // Eq. 7 agrees with r_a at the CoM and F the force the rod applies there to what loads it,
  // the opposite of the external force (gravity, −m g).
  EXPECT_NEAR(jacobian_joint_torque_nm({Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitY()},
                                       {p[0], p[1], p[2]}, {0.0, 0.0, m * g}),
              -m * g * L / 2, 1e-6);
  dWorldDestroy(world);
}

TEST(LegJacobianTorque, EquationSevenIsJacobianTransposeTimesForce) {
  const std::array<JointAxisFrame, 3> joints = {
      JointAxisFrame{{0.15, 0.12, 0.0}, {0.0, 0.0, 1.0}},
      JointAxisFrame{{0.17, 0.16, 0.0}, {0.8, -0.6, 0.0}},
      JointAxisFrame{{0.32, 0.36, 0.0}, {0.8, -0.6, 0.0}}};
  const Eigen::Vector3d tip(0.32, 0.36, -0.2), force(1.5, -2.0, -50.0);
  const Eigen::Vector3d tau = jacobian_leg_torques_nm(joints, tip, force);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(tau[i], jacobian_joint_torque_nm(joints[i], tip, force), 1e-12);
  }
  // Knee directly above the tip: only the horizontal force across the axis makes a moment,
  // ((0,0,−0.2) × F)·u = (0.2 F_y, −0.2 F_x, 0)·u.
  EXPECT_NEAR(tau[2], 0.2 * force.y() * 0.8 + (-0.2 * force.x()) * (-0.6), 1e-12);
}

}  // namespace
}  // namespace motoflex
