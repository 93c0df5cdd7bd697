#include "motoflex/studies/titan/titan_torque_probe.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "motoflex/studies/titan/leg_jacobian_torque.hpp"

namespace motoflex {
TitanTorqueProbe::TitanTorqueProbe(const RobotModel& model, const TitanKinematics& kinematics,
                                   Rollout& rollout)
    : model_(model), rollout_(rollout) {
  for (const TitanLeg leg : kTitanLegs) {
    for (std::size_t j = 0; j < 4; ++j) {
      const std::size_t actuator = kinematics.actuators(leg)[j];
      const JointSpec& spec = model.joints.at(model.actuators.at(actuator).joint);
      if (spec.kind != JointKind::kHinge) {
        throw std::invalid_argument("TITAN torque probe: " + spec.name + " is not a hinge");
      }
      JointRef& ref = joints_[index(leg)][j];
      ref.joint = static_cast<std::size_t>(model.actuators[actuator].joint);
      ref.child = static_cast<std::size_t>(spec.child_body);
      ref.parent = static_cast<std::size_t>(spec.parent_body);
      ref.actuator = actuator;
      // A Rollout hinge has body 1 = child (rollout.hpp), so feedback 1 acts on the child.
      if (!rollout.body_is_dynamic(ref.child) || !rollout.body_is_dynamic(ref.parent)) {
        throw std::invalid_argument("TITAN torque probe: " + spec.name +
                                    " must join two moving bodies");
      }
      rollout.enable_joint_feedback(ref.joint);
      if (j == 3) foot_body_[index(leg)] = spec.child_body;
    }
  }
  before_step();
}

void TitanTorqueProbe::before_step() {
  for (std::size_t l = 0; l < 4; ++l) {
    for (std::size_t j = 0; j < 4; ++j) {
      const JointRef& ref = joints_[l][j];
      Geometry& g = geometry_[l][j];
      rollout_.hinge_frame(ref.joint, g.anchor_m, g.axis);  // the anchor as attached to body 1
      g.child_com_m = rollout_.body_state(ref.child).position_m;
      g.parent_com_m = rollout_.body_state(ref.parent).position_m;
    }
  }
}

void TitanTorqueProbe::after_step() {
  for (std::size_t l = 0; l < 4; ++l) {
    TitanLegSample& s = samples_[l];
    std::array<Rollout::JointFeedback, 4> feedback;
    for (std::size_t j = 0; j < 4; ++j) feedback[j] = rollout_.joint_feedback(joints_[l][j].joint);
    for (std::size_t j = 0; j < 4; ++j) {
      const JointRef& ref = joints_[l][j];
      const Geometry& g = geometry_[l][j];
      const Rollout::JointFeedback& fb = feedback[j];
      s.angle_rad[j] = rollout_.joint_angle_rad(ref.actuator);
      s.rate_rad_s[j] = rollout_.joint_rate_rad_s(ref.actuator);
      // Seed 000 eq. 4–5 on the child (body 1).
      const JointWrench on_child =
          joint_wrench_at_point(fb.force1_n, fb.torque1_nm, g.child_com_m, g.anchor_m);
      s.feedback_torque_nm[j] = joint_axis_torque_nm(on_child, g.axis);
      if (j == 2) {
        const JointWrench on_parent =
            joint_wrench_at_point(fb.force2_n, fb.torque2_nm, g.parent_com_m, g.anchor_m);
        s.knee_load = joint_load(on_child);
        s.knee_third_law_residual_n = third_law_residual(on_child, on_parent).force_n.norm();
      }
    }
    // Seed 000 eq. 7: r_a = J4 position, F = the force J4 transmits to the foot (its f1).
    s.ankle_force_n = feedback[3].force1_n;
    std::array<JointAxisFrame, 3> leg_joints;
    for (std::size_t j = 0; j < 3; ++j)
      leg_joints[j] = {geometry_[l][j].anchor_m, geometry_[l][j].axis};
    const Eigen::Vector3d tau =
        jacobian_leg_torques_nm(leg_joints, geometry_[l][3].anchor_m, s.ankle_force_n);
    for (std::size_t j = 0; j < 3; ++j) s.jacobian_torque_nm[j] = tau[static_cast<int>(j)];
  }
}

double TitanTorqueProbe::foot_clearance_m(TitanLeg leg) const {
  const int b = foot_body_[index(leg)];
  const Rollout::BodyState body = rollout_.body_state(static_cast<std::size_t>(b));
  const Eigen::Vector3d& p = body.position_m;
  const Eigen::Matrix3d& R = body.R_WB;
  double lowest = std::numeric_limits<double>::infinity();
  for (const CollisionShape& box : model_.bodies[static_cast<std::size_t>(b)].collisions) {
    if (!box.is_foot || box.kind != ShapeKind::kBox) continue;
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d local(((corner & 1) ? 0.5 : -0.5) * box.size_m.x(),
                                  ((corner & 2) ? 0.5 : -0.5) * box.size_m.y(),
                                  ((corner & 4) ? 0.5 : -0.5) * box.size_m.z());
      const Eigen::Vector3d c = box.X_BG * local;  // body frame
      lowest = std::min(lowest, p.z() + R(2, 0) * c.x() + R(2, 1) * c.y() + R(2, 2) * c.z());
    }
  }
  return lowest;
}

double TitanTorqueProbe::potential_energy_j() const {
  const Eigen::Vector3d gravity = rollout_.gravity_m_s2();
  double energy = 0.0;
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    if (!rollout_.body_is_dynamic(b)) continue;
    const Rollout::BodyState body = rollout_.body_state(b);
    energy -= body.mass_kg * gravity.dot(body.position_m);
  }
  return energy;
}

double TitanTorqueProbe::kinetic_energy_j() const {
  double energy = 0.0;
  for (std::size_t b = 0; b < model_.bodies.size(); ++b) {
    if (!rollout_.body_is_dynamic(b)) continue;
    const Rollout::BodyState body = rollout_.body_state(b);
    const Eigen::Vector3d w_B = body.R_WB.transpose() * body.angular_velocity_rad_s;
    energy += 0.5 * body.mass_kg * body.velocity_m_s.squaredNorm() +
              0.5 * w_B.dot(body.inertia_B_kg_m2 * w_B);
  }
  return energy;
}

}  // namespace motoflex
